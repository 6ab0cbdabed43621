#pragma once
// `dgwarp deform`'s arguments and its text report of frames (the --json
// objects are the library's: job/method_run.hpp): shared by the one-process
// run (cmd_deform.cpp) and the run where each process reads its own
// processor folder (deform_processors.cpp).
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "deform_setup.hpp"
#include "dgwarp/job/method_run.hpp"
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

/// The single-frame table (quality before and after, ratio, times).
void print_single_frame(const Inputs& in, const JobFrame& f);
/// One line of a series; `timed`: the motion has times (periodic), so the
/// line shows the frame's (a frames list has none).
void print_frame_line(const JobFrame& f, bool timed);
/// A frame's text report: its warnings, then the single-frame table or the frame's line.
void print_frame(const Inputs& in, const JobFrame& f, std::size_t frames, WarningPrinter& warnings);

}  // namespace dgwarp::cli
