// dgwarp picture MESH -o OUT.png: a 2D mesh coloured by cell quality.
#include <iostream>
#include <memory>

#include "commands.hpp"
#include "flag_values.hpp"
#include "dgwarp/core/error.hpp"
#include "dgwarp/io/mesh_io.hpp"
#include "dgwarp/picture/mesh_picture.hpp"
#include "dgwarp/picture/picture_window.hpp"
#include "dgwarp/quality/mesh_quality.hpp"
#include "output_files.hpp"

namespace dgwarp::cli {

namespace {

struct PictureArgs {
    std::string mesh;
    std::string output;
    std::string reference;
    std::string around;
    double zoom = 3.0;
    std::vector<double> window;
    bool ratio = false;
    int width = PictureOptions{}.width, height = PictureOptions{}.height;
    std::string title;
    int zone = 1;
    bool quiet = false;
};

void run_picture(const PictureArgs& a) {
    if (!a.window.empty() && !(a.window[0] < a.window[1] && a.window[2] < a.window[3]))
        throw CLI::ValidationError("--window", "expected XMIN XMAX YMIN YMAX with XMIN < XMAX and YMIN < YMAX, got " +
                                                   CLI::detail::join(a.window, " "));
    require_extension("--output", a.output, {".png"}, "a PNG picture");
    std::vector<std::filesystem::path> inputs{a.mesh};
    if (!a.reference.empty()) inputs.emplace_back(a.reference);
    check_output_file(a.output, inputs);
    const Mesh mesh = read_mesh(a.mesh, {a.zone});
    std::vector<double> values;
    std::string label = "quality";
    if (!a.reference.empty()) {
        const Mesh reference = read_mesh(a.reference, {a.zone});
        if (reference.cells != mesh.cells)
            throw MeshError(a.reference + ": the reference mesh has other cells than " + a.mesh);
        const auto orientation = cell_orientations(reference);
        values = cell_qualities(mesh, orientation);
        if (a.ratio) {
            values = quality_ratios(values, cell_qualities(reference, orientation));
            label = "quality ratio";
        }
    } else {
        if (a.ratio) throw CLI::ValidationError("--ratio", "needs --reference ORIGINAL");
        values = cell_qualities(mesh, dominant_orientations(mesh));
    }
    PictureOptions options;
    options.width = a.width;
    options.height = a.height;
    options.title = a.title.empty() ? a.mesh : a.title;
    options.colorbar_label = label;
    if (!a.window.empty()) options.window = std::array<double, 4>{a.window[0], a.window[1], a.window[2], a.window[3]};
    if (!a.around.empty()) {
        const auto nodes = marker_nodes(find_marker(mesh, a.around));
        options.window = window_around(mesh, nodes, a.zoom, double(a.width) / a.height);
    }
    write_mesh_picture(a.output, mesh, values, options);
    if (!a.quiet) std::cout << "wrote " << a.output << "\n";
}

}  // namespace

void add_picture_command(CLI::App& app) {
    auto args = std::make_shared<PictureArgs>();
    CLI::App* cmd = app.add_subcommand("picture", "Draw a 2D mesh as a PNG picture, cells coloured by quality");
    cmd->add_option("mesh", args->mesh, "2D mesh file (.su2, .msh, .vtu, .cgns)")->required();
    cmd->add_option("-o,--output", args->output, "PNG file to write (NAME.png)")->required();
    cmd->add_option("--reference", args->reference, "The undeformed mesh: orientation (and --ratio) from it");
    cmd->add_flag("--ratio", args->ratio, "Colour by the per-cell quality ratio to --reference");
    cmd->add_option("--around", args->around, "Close-up of this marker (its nodes' bounding box, enlarged by --zoom)");
    cmd->add_option("--zoom", args->zoom, "Enlargement of the --around window")->capture_default_str()->check(positive_number());
    cmd->add_option("--window", args->window, "View window: XMIN XMAX YMIN YMAX")->expected(4)->check(finite_number());
    const auto picture_size = whole_number_between(min_picture_size, max_picture_size);
    cmd->add_option("--width", args->width, "Image width in pixels")->capture_default_str()->check(picture_size);
    cmd->add_option("--height", args->height, "Image height in pixels")->capture_default_str()->check(picture_size);
    cmd->add_option("--title", args->title, "Title (default: the file name)");
    cmd->add_option("--zone", args->zone, "Zone of a multi-zone SU2 file (1-based)")->check(positive_whole_number());
    cmd->add_flag("-q,--quiet", args->quiet, "Print nothing but errors");
    cmd->footer(
        "Inverted cells are red. The output's name ends in .png, and it may not be one of the inputs.\n\n"
        "Examples:\n"
        "  dgwarp picture naca0012.su2 -o mesh.png\n"
        "  dgwarp picture deformed.su2 --reference naca0012.su2 --around airfoil --zoom 1.5 -o te.png\n"
        "  dgwarp picture deformed.su2 --reference naca0012.su2 --ratio -o ratio.png");
    cmd->callback([args] { run_picture(*args); });
}

}  // namespace dgwarp::cli
