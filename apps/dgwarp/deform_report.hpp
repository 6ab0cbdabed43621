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
    bool foam_processors = false;  // also the processor folders beside the input's constant/polyMesh
    bool quiet = false;
    bool sync = false;  // each output synced to the disk before it is renamed into place (set_sync_writes)
};

/// A frame as the CLI reports it: the run layer's report (run/deform_frame.hpp)
/// and what the CLI adds (where it was written, MPI's per-process times).
struct FrameResult : FrameReport {
    std::size_t frame = 0;
    double time = 0;
    std::string output;  // empty when not written
    double write_seconds = 0;
    std::vector<double> process_seconds;  // under mpirun: each process's step
    bool own_parts = false;  // under mpirun, each process read its own processor folder (no scatter, no gather)
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

nlohmann::json frame_json(const FrameResult& f);
nlohmann::json run_json(const Inputs& in, const MethodRun& r);

/// The single-frame table (quality before and after, ratio, times).
void print_single_frame(const Inputs& in, const FrameResult& f);
/// One line of a series; `timed`: the motion has times (periodic), so the
/// line shows the frame's (a frames list has none).
void print_frame_line(const FrameResult& f, bool timed);
/// A frame's text report: its warnings, then the single-frame table or the frame's line.
void print_frame(const Inputs& in, const FrameResult& f, std::size_t frames, WarningPrinter& warnings);

}  // namespace dgwarp::cli
