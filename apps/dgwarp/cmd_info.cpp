// dgwarp info MESH: what a mesh holds.
#include <iomanip>
#include <iostream>
#include <memory>

#include "commands.hpp"
#include "flag_values.hpp"
#include "dgwarp/io/mesh_io.hpp"
#include "dgwarp/quality/mesh_quality.hpp"
#include "progress_line.hpp"
#include "report.hpp"

namespace dgwarp::cli {

namespace {

struct InfoArgs {
    std::string mesh;
    int zone = 1;
    bool json = false;
    bool quiet = false;
};

void run_info(const InfoArgs& a) {
    ProgressLine progress(!a.json && !a.quiet);
    MeshExtras extras;
    const Mesh mesh = read_mesh(a.mesh, {a.zone}, progress.reporter("reading " + a.mesh), extras);
    const std::int64_t zones = extras.su2 ? extras.su2->zones : 1;
    progress.phase("measuring quality");
    const BoundingBox box = bounding_box(mesh);
    const QualitySummary quality = summarize_quality(cell_qualities(mesh, dominant_orientations(mesh)));
    progress.clear();
    const auto d = static_cast<std::size_t>(mesh.dim);
    if (a.json) {
        nlohmann::json j = {{"schema_version", json_schema_version},
                            {"command", "info"},
                            {"file", a.mesh},
                            {"mesh", mesh_json(mesh)},
                            {"bounding_box",
                             {{"min", std::vector<double>(box.min.begin(), box.min.begin() + d)},
                              {"max", std::vector<double>(box.max.begin(), box.max.begin() + d)}}},
                            {"quality", quality_json(quality)},
                            {"zone", {{"number", a.zone}, {"of", zones}}}};
        std::cout << j.dump(2) << "\n";
        return;
    }
    if (a.quiet) return;
    std::cout << a.mesh << "\n  " << describe_mesh(mesh) << "\n";
    if (zones > 1) std::cout << "  zone " << a.zone << " of " << zones << " (--zone N reads another)\n";
    std::cout << "markers\n";
    for (const Marker& m : mesh.markers)
        std::cout << "  " << std::left << std::setw(24) << m.name << std::right << std::setw(9)
                  << m.elements.size() << " elements " << std::setw(9) << marker_nodes(m).size() << " nodes\n";
    std::cout << "bounding box\n";
    const char* axis = "xyz";
    for (std::size_t k = 0; k < d; ++k)
        std::cout << "  " << axis[k] << "  " << std::setw(14) << box.min[k] << " .. " << box.max[k] << "\n";
    std::cout << "Knupp shape quality (1 = ideal, <= 0 = inverted)\n";
    print_quality(std::cout, quality, false);
}

}  // namespace

void add_info_command(CLI::App& app) {
    auto args = std::make_shared<InfoArgs>();
    CLI::App* cmd = app.add_subcommand("info", "Show what a mesh holds: counts, markers, bounding box, quality");
    cmd->add_option("mesh", args->mesh, "Mesh file (.su2, .msh, .vtu, .cgns) or OpenFOAM case folder")->required();
    cmd->add_option("--zone", args->zone, "Zone of a multi-zone SU2 file (1-based)")->check(positive_whole_number());
    cmd->add_flag("--json", args->json, "Print a JSON report (schema in docs/JSON.md)");
    cmd->add_flag("-q,--quiet", args->quiet, "Print nothing but errors (the exit code says whether the mesh reads)");
    cmd->footer("Examples:\n  dgwarp info wing.su2\n  dgwarp info wing.msh --json");
    cmd->callback([args] { run_info(*args); });
}

}  // namespace dgwarp::cli
