#pragma once
// What `dgwarp deform` reports about its frames and methods (text and
// --json, docs/JSON.md): shared by the one-process run (cmd_deform.cpp) and
// the run where each process reads its own processor folder
// (deform_processors.cpp).
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "deform_setup.hpp"
#include "dgwarp/repair/untangle.hpp"
#include "warning_printer.hpp"

namespace dgwarp::cli {

struct DeformArgs {
    SetupArgs setup;
    std::string output;
    std::string plan;
    bool json = false;
    bool allow_invalid = false;
    bool untangle = false;
    bool no_untangle = false;  // dg-harmonic without its last resort
    double untangle_target = UntangleOptions{}.target_quality;
    std::string foam_time;  // OpenFOAM output: a single frame's time folder, or "constant"
    bool quiet = false;
};

struct FrameResult {
    std::size_t frame = 0;
    double time = 0;
    std::string output;  // empty when not written
    QualitySummary quality;
    RatioSummary ratio;
    StepReport step;
    std::int64_t inverted_by_motion = 0;       // cells valid in the input and inverted now (what makes a frame invalid)
    std::vector<std::int64_t> worst_inverted;  // the worst of those
    // Of those, the cells whose every node is on the boundary: the boundary
    // motion alone inverts them, and nothing that moves volume nodes can help.
    std::int64_t inverted_on_boundary = 0;
    std::vector<std::int64_t> worst_on_boundary;  // the worst of those
    std::optional<UntangleReport> untangled;  // when --untangle (or dg-harmonic's last resort) found cells to repair
    bool last_resort = false;                 // the repair was dg-harmonic's last resort, not --untangle
    double deform_seconds = 0, untangle_seconds = 0, quality_seconds = 0, write_seconds = 0;
    std::vector<double> process_seconds;  // under mpirun: each process's step
    bool own_parts = false;  // under mpirun, each process read its own processor folder (no scatter, no gather)
    std::vector<std::string> warnings;
};

/// One method's run over every frame.
struct MethodRun {
    PlannedMethod planned;
    std::vector<FrameResult> frames;
    std::string error;  // why the method stopped (invalid graph, too large, ...), "" if it ran
    bool invalid = false;  // a frame had inverted cells, or the method could not produce a valid mesh
    bool failed = false;   // the method stopped with an error before producing a mesh (with --method all)
};

/// "3, 7, 12".
std::string cell_list(const std::vector<std::int64_t>& cells);

/// Why frame `bad` (with inverted cells) makes the run invalid.
std::string invalid_frame_error(const FrameResult& bad);

/// Appends frame `f` to `run`; a frame with cells the motion inverted makes
/// the run invalid (invalid_frame_error). Whether the run goes on: not after
/// an invalid frame unless `allow_invalid` (nothing more is written then).
bool add_frame(MethodRun& run, FrameResult f, bool allow_invalid);

nlohmann::json untangle_json(const UntangleReport& u);
nlohmann::json frame_json(const FrameResult& f);
nlohmann::json run_json(const Inputs& in, const MethodRun& r);

/// The single-frame table (quality before and after, ratio, times).
void print_single_frame(const Inputs& in, const FrameResult& f);
/// One line of a series; `timed`: the motion has times (periodic), so the
/// line shows the frame's (a frames list has none).
void print_frame_line(const FrameResult& f, bool timed);
/// A frame's text report: its warnings, then the single-frame table or the frame's line.
void print_frame(const Inputs& in, const FrameResult& f, const std::vector<std::string>& motion_warnings,
                 const std::vector<std::string>& step_warning_texts, std::size_t frames, WarningPrinter& warnings);

}  // namespace dgwarp::cli
