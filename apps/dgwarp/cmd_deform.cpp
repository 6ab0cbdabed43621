// dgwarp deform MESH --motion M.json -o OUT: move the mesh with its boundary.
#include <cstdio>
#include <iomanip>
#include <iostream>
#include <memory>
#include <sstream>

#include "commands.hpp"
#include "deform_setup.hpp"
#include "dgwarp/core/error.hpp"
#include "dgwarp/io/mesh_io.hpp"
#include "dgwarp/quality/mesh_quality.hpp"
#include "frame_output.hpp"
#include "report.hpp"
#include "stopwatch.hpp"

namespace dgwarp::cli {

namespace {

struct DeformArgs {
    SetupArgs setup;
    std::string output;
    std::string plan;
    bool json = false;
    bool allow_invalid = false;
    bool quiet = false;
};

struct FrameResult {
    std::size_t frame = 0;
    double time = 0;
    std::string output;  // empty when not written
    QualitySummary quality;
    RatioSummary ratio;
    std::vector<std::int64_t> worst_inverted;
    double deform_seconds = 0, quality_seconds = 0, write_seconds = 0;
    std::vector<std::string> warnings;
};

std::string ms(double seconds) {
    std::ostringstream s;
    s << std::fixed << std::setprecision(seconds < 0.01 ? 2 : 1) << seconds * 1e3 << " ms";
    return s.str();
}

std::string cell_list(const std::vector<std::int64_t>& cells) {
    std::string s;
    for (auto c : cells) s += (s.empty() ? "" : ", ") + std::to_string(c);
    return s;
}

nlohmann::json frame_json(const FrameResult& f) {
    return {{"frame", f.frame},
            {"time", f.time},
            {"output", f.output.empty() ? nlohmann::json(nullptr) : nlohmann::json(f.output)},
            {"quality", quality_json(f.quality)},
            {"ratio", ratio_json(f.ratio)},
            {"worst_inverted_cells", f.worst_inverted},
            {"seconds", {{"deform", f.deform_seconds}, {"quality", f.quality_seconds}, {"write", f.write_seconds}}},
            {"warnings", f.warnings}};
}

void print_single_frame(const Setup& s, const FrameResult& f) {
    std::cout << "quality (Knupp shape)   before      after\n" << std::fixed << std::setprecision(6);
    std::cout << "  min               " << std::setw(10) << s.original_quality.min << "  " << std::setw(10)
              << f.quality.min << "  (cell " << f.quality.worst_cell << ")\n";
    std::cout << "  mean              " << std::setw(10) << s.original_quality.mean << "  " << std::setw(10)
              << f.quality.mean << "\n";
    std::cout << "  inverted          " << std::setw(10) << s.original_quality.inverted << "  " << std::setw(10)
              << f.quality.inverted << "\n";
    std::cout << "ratio after/before, per cell: min " << f.ratio.min << " (cell " << f.ratio.worst_cell
              << "), mean " << f.ratio.mean << "\n";
    std::cout.unsetf(std::ios::floatfield);
    std::cout << "time      deform " << ms(f.deform_seconds) << ", quality " << ms(f.quality_seconds)
              << ", write " << ms(f.write_seconds) << "\n";
}

void print_frame_line(const FrameResult& f) {
    char line[200];
    std::snprintf(line, sizeof line, "frame %4zu  t=%-10g min %.6f  mean %.6f  inverted %lld  ratio min %.4f  deform %s",
                  f.frame, f.time, f.quality.min, f.quality.mean, static_cast<long long>(f.quality.inverted),
                  f.ratio.min, ms(f.deform_seconds).c_str());
    std::cout << line << (f.output.empty() ? "" : "  -> " + f.output) << "\n";
}

void run_deform(const DeformArgs& a) {
    const bool text = !a.json && !a.quiet;
    ProgressLine progress(text);
    Setup s = set_up(a.setup, a.plan, progress);
    const std::size_t frames = frame_count(s.spec);
    if (text) print_setup(std::cout, s, frames);

    Mesh deformed = s.mesh;
    std::vector<FrameResult> results;
    std::int64_t invalid_frames = 0;
    for (std::size_t k = 0; k < frames; ++k) {
        FrameResult f;
        f.frame = k;
        f.time = frame_time(s.spec, k);
        if (frames > 1) progress.step("deforming frame", k + 1, frames);
        Stopwatch sw;
        const ResolvedFrame motion = resolve_frame(s.mesh, s.spec, s.boundary.boundary, k);
        f.warnings = motion.warnings;
        deform_mesh(s, motion.motion, deformed.points);
        f.deform_seconds = sw.lap();
        const std::vector<double> quality = cell_qualities(deformed, s.orientation);
        const std::vector<double> ratio = quality_ratios(quality, s.original_cell_quality);
        f.quality = summarize_quality(quality);
        f.ratio = summarize_ratios(ratio);
        f.worst_inverted = worst_inverted_cells(quality, 10);
        f.quality_seconds = sw.lap();
        const bool invalid = f.quality.inverted > 0;
        if (!invalid || a.allow_invalid) {
            const auto path = frame_path(a.output, k, frames);
            write_mesh(path, deformed, deformation_fields(s.mesh, deformed.points, quality, ratio));
            f.output = path.string();
            f.write_seconds = sw.lap();
        }
        if (text) {
            progress.clear();
            for (const auto& w : f.warnings) std::cerr << "warning: frame " << k << ": " << w << "\n";
            if (frames == 1)
                print_single_frame(s, f);
            else
                print_frame_line(f);
            if (!f.output.empty() && frames == 1) std::cout << "wrote " << f.output << "\n";
        }
        results.push_back(std::move(f));
        if (invalid) {
            ++invalid_frames;
            if (!a.allow_invalid) break;  // nothing more is written after an invalid frame
        }
    }

    if (a.json) {
        nlohmann::json j = setup_json(s, "deform");
        j["output"] = a.output;
        j["frames"] = nlohmann::json::array();
        for (const auto& f : results) j["frames"].push_back(frame_json(f));
        j["valid"] = invalid_frames == 0;
        std::cout << j.dump(2) << "\n";
    }
    if (invalid_frames > 0) {
        const FrameResult& f = results.back();
        const std::string what = std::to_string(f.quality.inverted) + " inverted cell" +
                                 (f.quality.inverted == 1 ? "" : "s") + " in frame " + std::to_string(f.frame) +
                                 " (worst: " + cell_list(f.worst_inverted) + ")";
        if (!a.allow_invalid)
            throw InvalidResultError(what + "; nothing was written for it. The motion is too large for one step: "
                                            "split it into frames, or use --allow-invalid to write it anyway",
                                     f.quality.inverted);
        if (!a.quiet) std::cerr << "warning: " << what << "; written anyway (--allow-invalid)\n";
    }
}

}  // namespace

void add_deform_command(CLI::App& app) {
    auto args = std::make_shared<DeformArgs>();
    CLI::App* cmd = app.add_subcommand("deform", "Deform a mesh to follow the motion of its boundary markers");
    add_setup_options(cmd, args->setup);
    cmd->add_option("-o,--output", args->output,
                    "Output mesh (.su2, .msh, .vtu; VTU adds displacement and quality); a time series writes "
                    "one file per frame, numbered before the extension")
        ->required();
    cmd->add_option("--plan", args->plan, "Use a plan saved by 'dgwarp prepare' instead of building it");
    cmd->add_flag("--allow-invalid", args->allow_invalid, "Write the result even if cells are inverted");
    cmd->add_flag("--json", args->json, "Print a JSON report (schema in docs/JSON.md)");
    cmd->add_flag("-q,--quiet", args->quiet, "Print nothing but errors");
    cmd->footer(
        "The motion file names each moving marker's motion (docs/MOTION.md); markers not named stay fixed.\n"
        "Exit code 3 when a cell is inverted: nothing is written for that frame unless --allow-invalid.\n\n"
        "Examples:\n"
        "  dgwarp deform naca0012.su2 --motion rotate45.json -o deformed.vtu\n"
        "  dgwarp deform naca0012.su2 --motion pitching.json -o frames/pitch.su2    (one file per frame)\n"
        "  dgwarp prepare wing.su2 --motion fold.json -o wing.plan\n"
        "  dgwarp deform wing.su2 --motion fold.json --plan wing.plan -o folded.su2 --json");
    cmd->callback([args] { run_deform(*args); });
}

}  // namespace dgwarp::cli
