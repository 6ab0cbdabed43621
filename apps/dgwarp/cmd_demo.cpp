// dgwarp demo: the built-in example, run by the README's first command.
#include <filesystem>
#include <iostream>
#include <memory>

#include "commands.hpp"
#include "dgwarp/cases/rect_box.hpp"
#include "dgwarp/io/mesh_io.hpp"
#include "dgwarp/quality/mesh_quality.hpp"
#include "report.hpp"

namespace dgwarp::cli {

namespace {

struct DemoArgs {
    std::string folder = "dgwarp-demo";
};

void run_demo(const DemoArgs& a) {
    std::filesystem::create_directories(a.folder);
    const std::filesystem::path dir = std::filesystem::absolute(a.folder);

    std::cout << "dgwarp demo: the paper's first case, a rectangle in a box (structured quadrilaterals)\n";
    const Mesh mesh = make_rect_box();
    std::cout << "  mesh: " << describe_mesh(mesh) << "\n";
    const auto orientation = cell_orientations(mesh);
    const std::vector<double> quality = cell_qualities(mesh, orientation);
    std::cout << "Knupp shape quality of the original mesh\n";
    print_quality(std::cout, summarize_quality(quality), false);

    MeshFields fields;
    fields.cell_data.push_back({"quality", 1, quality});
    write_mesh(dir / "rect_box.su2", mesh);
    write_mesh(dir / "rect_box.vtu", mesh, fields);
    std::cout << "wrote\n  " << (dir / "rect_box.su2").string() << "  (SU2 mesh)\n  "
              << (dir / "rect_box.vtu").string() << "  (open in ParaView; cell data 'quality')\n";
}

}  // namespace

void add_demo_command(CLI::App& app) {
    auto args = std::make_shared<DemoArgs>();
    CLI::App* cmd = app.add_subcommand("demo", "Run the built-in example and write its results to a folder");
    cmd->add_option("-o,--output", args->folder, "Folder for the results (created if needed)")->capture_default_str();
    cmd->footer("Examples:\n  dgwarp demo\n  dgwarp demo -o /tmp/dgwarp-demo");
    cmd->callback([args] { run_demo(*args); });
}

}  // namespace dgwarp::cli
