// dgwarp quality MESH: Knupp shape quality summary of a mesh.
#include <iostream>
#include <memory>

#include "commands.hpp"
#include "dgwarp/core/error.hpp"
#include "dgwarp/io/mesh_io.hpp"
#include "dgwarp/quality/mesh_quality.hpp"
#include "flag_values.hpp"
#include "progress_line.hpp"
#include "report.hpp"

namespace dgwarp::cli {

namespace {

struct QualityArgs {
    std::string mesh;
    std::string reference;
    int zone = 1;
    int threads = 0;
    bool json = false;
    bool histogram = false;
    bool quiet = false;
};

void run_quality(const QualityArgs& a) {
    use_threads(a.threads);
    ProgressLine progress(!a.json && !a.quiet);
    const Mesh mesh = read_mesh(a.mesh, {a.zone}, progress.reporter("reading " + a.mesh));
    std::vector<std::int8_t> orientation;
    std::vector<double> original_quality;
    if (!a.reference.empty()) {
        const Mesh reference = read_mesh(a.reference, {a.zone}, progress.reporter("reading " + a.reference));
        progress.phase("measuring quality");
        if (reference.cells != mesh.cells)
            throw MeshError(a.reference + ": the reference mesh has other cells than " + a.mesh +
                            " (it must be the same mesh before deformation)");
        orientation = cell_orientations(reference);
        original_quality = cell_qualities(reference, orientation);
    } else {
        orientation = dominant_orientations(mesh);
    }
    progress.phase("measuring quality");
    const std::vector<double> quality = cell_qualities(mesh, orientation);
    const QualitySummary summary = summarize_quality(quality);
    progress.clear();

    if (a.json) {
        nlohmann::json j = {{"schema_version", json_schema_version},
                            {"command", "quality"},
                            {"file", a.mesh},
                            {"mesh", mesh_json(mesh)},
                            {"quality", quality_json(summary)}};
        if (!a.reference.empty()) {
            j["reference"] = a.reference;
            j["ratio"] = ratio_json(summarize_ratios(quality_ratios(quality, original_quality)));
        }
        std::cout << j.dump(2) << "\n";
        return;
    }
    if (a.quiet) return;
    std::cout << a.mesh << ": " << describe_mesh(mesh) << "\n";
    std::cout << "Knupp shape quality (1 = ideal, <= 0 = inverted)"
              << (a.reference.empty() ? "" : ", orientation from " + a.reference) << "\n";
    print_quality(std::cout, summary, a.histogram);
    if (!a.reference.empty()) {
        std::cout << "ratio to the reference mesh, per cell\n";
        print_ratio(std::cout, summarize_ratios(quality_ratios(quality, original_quality)));
    }
}

}  // namespace

void add_quality_command(CLI::App& app) {
    auto args = std::make_shared<QualityArgs>();
    CLI::App* cmd = app.add_subcommand("quality", "Print the shape quality of a mesh's cells (Knupp's metric)");
    cmd->add_option("mesh", args->mesh, "Mesh file (.su2, .msh, .vtu, .cgns) or OpenFOAM case folder")->required();
    cmd->add_option("--reference", args->reference,
                    "The undeformed mesh: judge orientation against it and report the per-cell ratio "
                    "deformed/original (what matters on boundary-layer meshes)");
    cmd->add_option("--zone", args->zone, "Zone of a multi-zone SU2 file (1-based)")->check(positive_whole_number());
    add_threads_option(cmd, args->threads, "all cores");
    cmd->add_flag("--json", args->json, "Print a JSON report (schema in docs/JSON.md)");
    cmd->add_flag("--histogram", args->histogram, "Also print the quality histogram");
    cmd->add_flag("-q,--quiet", args->quiet, "Print nothing but errors");
    cmd->footer(
        "Quality is Knupp's shape metric: 1 for the ideal cell, 0 for a degenerate one, <= 0 for an\n"
        "inverted one. Without --reference, a cell is inverted when it is oriented against most cells.\n\n"
        "Examples:\n"
        "  dgwarp quality wing.su2\n"
        "  dgwarp quality wing.su2 --histogram\n"
        "  dgwarp quality deformed.su2 --reference wing.su2 --json");
    cmd->callback([args] { run_quality(*args); });
}

}  // namespace dgwarp::cli
