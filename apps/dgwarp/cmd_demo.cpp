// dgwarp demo: the built-in example, run by the README's first command.
#include <filesystem>
#include <iostream>
#include <memory>
#include <numbers>

#include "commands.hpp"
#include "dgwarp/cases/rect_box.hpp"
#include "dgwarp/core/error.hpp"
#include "dgwarp/core/stopwatch.hpp"
#include "dgwarp/io/mesh_io.hpp"
#include "dgwarp/job/frame_outputs.hpp"
#include "dgwarp/methods/method.hpp"
#include "dgwarp/motion/resolve_motion.hpp"
#include "dgwarp/picture/mesh_picture.hpp"
#include "dgwarp/picture/picture_window.hpp"
#include "dgwarp/quality/mesh_quality.hpp"
#include "deform_setup.hpp"
#include "dgwarp/io/number_text.hpp"
#include "flag_values.hpp"
#include "output_files.hpp"
#include "report.hpp"

namespace dgwarp::cli {

namespace {

struct DemoArgs {
    std::string folder = "dgwarp-demo";
    double angle_deg = 30;
    bool quiet = false;
};

// The rectangle turned about its centre and moved a little; the far field stays.
MotionSpec demo_motion(double angle_deg) {
    RigidMotion rigid;
    rigid.motion.rotation = {0, 0, angle_deg * std::numbers::pi / 180};
    rigid.motion.translation = {0.5, 0.25, 0};
    MotionFrame frame;
    frame.markers["rectangle"] = rigid;
    MotionSpec spec;
    spec.frames = {frame};
    return spec;
}

void run_demo(const DemoArgs& a) {
    // The result written is that of the method deform runs by default.
    const Method shown = method_from_name(SetupArgs{}.method).value();
    const std::string name(method_name(shown));
    const std::string stem = "rect_box_" + name;
    make_output_folder(a.folder);
    const std::filesystem::path dir = std::filesystem::absolute(a.folder);
    for (const std::string& file : {std::string("rect_box.su2"), stem + ".vtu", stem + ".png", stem + "_closeup.png",
                                   std::string("rect_box.png")})
        check_output(dir / file, {});
    std::ostream discard(nullptr);  // -q: the report goes nowhere
    std::ostream& out = a.quiet ? discard : std::cout;
    char line[256];

    out << "dgwarp demo: the paper's first case, a rectangle in a box (structured quadrilaterals),\n"
              << "the rectangle turned by " << a.angle_deg << " degrees and moved by (0.5, 0.25); the box stays.\n";
    const Mesh mesh = make_rect_box();
    out << "  mesh: " << describe_mesh(mesh) << "\n";
    const MotionSpec spec = demo_motion(a.angle_deg);
    const ResolvedBoundary boundary = resolve_boundary(mesh, spec);
    const BoundaryMotion motion = resolve_frame(mesh, spec, boundary, 0).motion;
    const auto orientation = cell_orientations(mesh);
    const std::vector<double> original_quality = cell_qualities(mesh, orientation);

    out << "\nmethod       prepare     deform     min quality  mean quality  inverted\n";
    std::snprintf(line, sizeof line, "%-11s  %9s  %9s  %11.4f  %12.4f  %8d\n", "original", "", "",
                  summarize_quality(original_quality).min, summarize_quality(original_quality).mean, 0);
    out << line;
    Mesh deformed = mesh;
    std::vector<double> shown_points, shown_quality;
    std::string shown_failure;  // why the shown method's result is not written
    for (Method m : all_methods) {
        Stopwatch sw;
        try {
            const Plan plan = prepare(m, mesh.dim, mesh.points, mesh.cells, boundary.boundary);
            const double prepare_seconds = sw.lap();
            deform(plan, mesh.points, motion, deformed.points);
            const double deform_seconds = sw.lap();
            const std::vector<double> q = cell_qualities(deformed, orientation);
            const QualitySummary s = summarize_quality(q);
            std::snprintf(line, sizeof line, "%-11s  %9s  %9s  %11.4f  %12.4f  %8lld\n",
                          std::string(method_name(m)).c_str(), milliseconds(prepare_seconds).c_str(),
                          milliseconds(deform_seconds).c_str(), s.min, s.mean, static_cast<long long>(s.inverted));
            out << line;
            if (m == shown) {
                shown_points = deformed.points;
                shown_quality = q;
                if (s.inverted > 0)
                    shown_failure = std::to_string(s.inverted) + " inverted cell" + (s.inverted == 1 ? "" : "s");
            }
        } catch (const InvalidResultError& e) {
            std::snprintf(line, sizeof line, "%-11s  ", std::string(method_name(m)).c_str());
            out << line << e.what() << "\n";
            if (m == shown) shown_failure = e.what();
        }
    }

    write_mesh(dir / "rect_box.su2", mesh);
    PictureOptions picture;
    picture.title = "original mesh";
    write_mesh_picture(dir / "rect_box.png", mesh, original_quality, picture);
    // As deform: an invalid result is not written (the table above shows every method's).
    if (!shown_failure.empty())
        throw InvalidResultError(name + " (the default method): " + shown_failure + " with the rectangle turned by " +
                                     number_text(a.angle_deg) + " degrees; only the original mesh was written (" +
                                     (dir / "rect_box.su2").string() + "). Try a smaller --angle",
                                 1);
    deformed.points = shown_points;
    const std::vector<double> ratio = quality_ratios(shown_quality, original_quality);
    write_mesh(dir / (stem + ".vtu"), deformed, deformation_fields(mesh, deformed.points, shown_quality, ratio));
    picture.title = name + ": rectangle turned by " + number_text(a.angle_deg) +
                    " degrees, coloured by Knupp shape quality";
    write_mesh_picture(dir / (stem + ".png"), deformed, shown_quality, picture);
    const auto rect_nodes = marker_nodes(find_marker(mesh, "rectangle"));
    picture.window = window_around(deformed, rect_nodes, 6.0);
    picture.title = name + ", close to the rectangle";
    write_mesh_picture(dir / (stem + "_closeup.png"), deformed, shown_quality, picture);
    out << "\nwrote\n  " << (dir / "rect_box.su2").string() << "  (original mesh, SU2)\n  "
        << (dir / (stem + ".vtu")).string() << "  (" << name
        << " result, the default method's: open in ParaView; displacement, quality, quality_ratio)\n  "
        << (dir / (stem + ".png")).string() << "  (" << name << " result, coloured by quality)\n  "
        << (dir / (stem + "_closeup.png")).string() << "  (the same, close to the rectangle)\n  "
        << (dir / "rect_box.png").string() << "  (original mesh)\n"
        << "next: dgwarp deform --help, and README.md for your own meshes and motions\n";
}

}  // namespace

void add_demo_command(CLI::App& app) {
    auto args = std::make_shared<DemoArgs>();
    CLI::App* cmd = app.add_subcommand("demo", "Run the built-in example and write its results to a folder");
    cmd->add_option("-o,--output", args->folder, "Folder for the results (created if needed)")->capture_default_str();
    cmd->add_option("--angle", args->angle_deg, "Rotation of the rectangle, degrees")
        ->capture_default_str()
        ->check(number_between(-360, 360));
    cmd->add_flag("-q,--quiet", args->quiet, "Print nothing but errors");
    cmd->footer(
        "Runs the five methods and prints their quality; writes the original mesh and the default method's\n"
        "(dg-harmonic's) result as VTU and PNG. When that result has inverted cells, it is not written and the\n"
        "exit code is 3, as for deform.\n\n"
        "Examples:\n  dgwarp demo\n  dgwarp demo -o /tmp/dgwarp-demo --angle 20");
    cmd->callback([args] { run_demo(*args); });
}

}  // namespace dgwarp::cli
