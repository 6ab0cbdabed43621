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
#include "dgwarp/methods/method.hpp"
#include "dgwarp/motion/resolve_motion.hpp"
#include "dgwarp/picture/mesh_picture.hpp"
#include "dgwarp/picture/picture_window.hpp"
#include "dgwarp/quality/mesh_quality.hpp"
#include "flag_values.hpp"
#include "frame_output.hpp"
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
    make_output_folder(a.folder);
    const std::filesystem::path dir = std::filesystem::absolute(a.folder);
    for (const char* name : {"rect_box.su2", "rect_box_dg-idw.vtu", "rect_box_dg-idw.png", "rect_box_dg-idw_closeup.png",
                             "rect_box.png"})
        check_output(dir / name, {});
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
    std::vector<double> dg_idw_points, dg_idw_quality;
    for (Method m : all_methods) {
        std::string status;
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
            if (m == Method::dg_idw) {
                dg_idw_points = deformed.points;
                dg_idw_quality = q;
            }
        } catch (const InvalidResultError& e) {
            std::snprintf(line, sizeof line, "%-11s  ", std::string(method_name(m)).c_str());
            out << line << e.what() << "\n";
        }
    }

    deformed.points = dg_idw_points;
    const std::vector<double> ratio = quality_ratios(dg_idw_quality, original_quality);
    write_mesh(dir / "rect_box.su2", mesh);
    write_mesh(dir / "rect_box_dg-idw.vtu", deformed, deformation_fields(mesh, deformed.points, dg_idw_quality, ratio));
    PictureOptions picture;
    picture.title = "DG-IDW: rectangle turned by " + std::to_string(static_cast<int>(a.angle_deg)) +
                    " degrees, coloured by Knupp shape quality";
    write_mesh_picture(dir / "rect_box_dg-idw.png", deformed, dg_idw_quality, picture);
    const auto rect_nodes = marker_nodes(find_marker(mesh, "rectangle"));
    picture.window = window_around(deformed, rect_nodes, 6.0);
    picture.title = "DG-IDW, close to the rectangle";
    write_mesh_picture(dir / "rect_box_dg-idw_closeup.png", deformed, dg_idw_quality, picture);
    picture.window.reset();
    picture.title = "original mesh";
    write_mesh_picture(dir / "rect_box.png", mesh, original_quality, picture);
    out << "\nwrote\n  " << (dir / "rect_box.su2").string() << "  (original mesh, SU2)\n  "
              << (dir / "rect_box_dg-idw.vtu").string()
              << "  (DG-IDW result: open in ParaView; displacement, quality, quality_ratio)\n  "
              << (dir / "rect_box_dg-idw.png").string() << "  (DG-IDW result, coloured by quality)\n  "
              << (dir / "rect_box_dg-idw_closeup.png").string() << "  (the same, close to the rectangle)\n  "
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
    cmd->footer("Examples:\n  dgwarp demo\n  dgwarp demo -o /tmp/dgwarp-demo --angle 20");
    cmd->callback([args] { run_demo(*args); });
}

}  // namespace dgwarp::cli
