// dgwarp check MESH -m MOTION: everything deform checks about a motion and a
// mesh, for every frame, without deforming.
#include <iostream>
#include <memory>
#include <set>

#include "commands.hpp"
#include "deform_setup.hpp"
#include "dgwarp/core/stopwatch.hpp"
#include "report.hpp"
#include "warning_printer.hpp"

namespace dgwarp::cli {

namespace {

struct CheckArgs {
    SetupArgs setup;
    bool json = false;
    bool quiet = false;
};

void run_check(const CheckArgs& a) {
    const bool text = !a.json && !a.quiet;
    ProgressLine progress(text);
    // Reading and resolve_boundary check the files, the markers, the node
    // files and the moving/static split (and the frames a frame list writes
    // out); resolving every frame checks what only a later step of a periodic
    // motion shows (moving markers that disagree on shared nodes).
    const Inputs in = read_motion_inputs(a.setup, progress);
    const std::size_t frames = frame_count(in.spec);
    WarningPrinter printer(text);
    if (text) print_inputs(std::cout, in, frames, printer);
    std::vector<Warning> warnings = in.boundary.warnings;
    // resolve_boundary has already given the warnings of the frames it
    // resolved (a frame list's, step 0 of a periodic motion): once is enough.
    std::set<std::string> seen;
    for (const Warning& w : warnings) seen.insert(w.text);
    Stopwatch sw;
    for (std::size_t k = 0; k < frames; ++k) {
        progress.fraction("checking the frames", static_cast<double>(k) / static_cast<double>(frames));
        for (const Warning& w : resolve_frame(in.mesh, in.spec, in.boundary, k).warnings) {
            if (!seen.insert(w.text).second) continue;
            printer.print(w.text, "frame " + std::to_string(k) + ": ");
            warnings.push_back(w);
        }
    }
    const double frames_seconds = sw.lap();
    progress.clear();
    if (a.json) {
        const nlohmann::json j = {{"schema_version", json_schema_version},
                                  {"command", "check"},
                                  {"file", in.args.mesh},
                                  {"motion", in.args.motion},
                                  {"mesh", mesh_json(in.mesh)},
                                  {"boundary", boundary_json(in)},
                                  {"frames", frames},
                                  {"seconds",
                                   {{"read", in.read_seconds},
                                    {"resolve", in.resolve_seconds},
                                    {"frames", frames_seconds}}},
                                  {"warnings", warning_texts_json(warnings)},
                                  {"warning_items", warning_items_json(warnings)}};
        std::cout << j.dump(2) << "\n";
    } else if (text) {
        std::cout << "check     ok: " << frames << " frame" << (frames == 1 ? "" : "s") << " resolved, "
                  << warnings.size() << " warning" << (warnings.size() == 1 ? "" : "s") << "\n";
    }
}

}  // namespace

void add_check_command(CLI::App& app) {
    auto args = std::make_shared<CheckArgs>();
    CLI::App* cmd = app.add_subcommand(
        "check", "Check a motion against a mesh (markers, node files, moving/static split, conflicts) without deforming");
    add_input_options(cmd, args->setup);
    cmd->add_flag("--json", args->json, "Print a JSON report (schema in docs/JSON.md)");
    cmd->add_flag("-q,--quiet", args->quiet, "Print nothing but errors");
    cmd->footer(
        "Reads the mesh and the motion and resolves every frame as deform does: unknown markers, node files that\n"
        "do not cover their markers, 2D motions out of the plane, moving markers that disagree on shared nodes\n"
        "are errors (exit code 2, the message names the file, marker, node and frame); suspicious input gives\n"
        "warnings on standard error (exit code 0). Nothing is deformed or written.\n\n"
        "Examples:\n"
        "  dgwarp check naca0012.su2 -m examples/motions/airfoil_rotate.json\n"
        "  dgwarp check naca0012.su2 -m examples/motions/airfoil_pitch_plunge.json --json");
    cmd->callback([args] { run_check(*args); });
}

}  // namespace dgwarp::cli
