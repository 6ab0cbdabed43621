#pragma once
// One method's run of a job: every frame stepped from the original mesh
// (run/run_deformation.hpp), written (frame_outputs.hpp) and reported; a
// job may run several methods in turn (`dgwarp deform --method all`), each
// a MethodRun of its own.
//
//   MethodRun run;
//   run.planned = plan_job(in, request);
//   FrameOutputs outputs{"out.su2", frame_count(in.spec)};
//   run_method(in, run, outputs, {}, {});
//   if (run.invalid) throw InvalidResultError(run.error, 1);
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "dgwarp/job/frame_outputs.hpp"
#include "dgwarp/job/job_inputs.hpp"
#include "dgwarp/job/job_plan.hpp"
#include "dgwarp/run/run_deformation.hpp"

namespace dgwarp {

/// A frame of a job: the run layer's report and where it was written.
struct JobFrame : FrameReport {
    std::size_t frame = 0;
    double time = 0;
    std::string output;  // the file written, "" when not written
    double write_seconds = 0;
    std::vector<double> process_seconds;  // spread over processes: each process's step
    bool own_parts = false;  // spread over processes, each read its own part (no scatter, no gather)
};

/// One method's run over the frames.
struct MethodRun {
    JobPlan planned;
    std::vector<JobFrame> frames;
    std::string error;     // why the method stopped (a frame's inverted cells, an error), "" if it ran
    bool invalid = false;  // a frame had inverted cells, or the method could not produce a valid mesh
    bool failed = false;   // the method stopped with an error before producing a mesh
};

/// "3, 7, 12".
std::string cell_list(const std::vector<std::int64_t>& cells);

/// Why frame `bad` (with cells the motion inverted) makes the run invalid:
/// how many, the worst, and those the boundary motion itself folds.
std::string invalid_frame_error(const JobFrame& bad);

/// Appends frame `f` to `run`; a frame with cells the motion inverted makes
/// the run invalid (invalid_frame_error). Whether the run goes on: not
/// after an invalid frame unless `write_invalid`.
bool add_frame(MethodRun& run, JobFrame f, bool write_invalid);

struct MethodRunOptions {
    FrameOptions frame;          // the repair (run/deform_frame.hpp)
    bool write_invalid = false;  // write a frame with inverted cells, and go on
    /// An error of a step (not of reading a frame's motion, nor of writing)
    /// ends this method's run, kept in run.error, rather than the job: a job
    /// running several methods goes on with the others.
    bool keep_step_errors = false;
};

/// Every frame of in.spec with run.planned's plan: each valid one (or
/// every one with options.write_invalid) written with write_frame, added
/// to `run` (add_frame), and handed to `reported` (when given; it may add
/// what it knows, e.g. process_seconds) before the next. `on` is the run
/// layer's (frame_started, repair_started, step, step_running) but for its
/// frame_done, which is this function's (`reported` sees each frame). Throws what run_frames
/// and write_frame throw (a step's error is kept instead with
/// options.keep_step_errors).
void run_method(JobInputs& in, MethodRun& run, FrameOutputs& outputs, const MethodRunOptions& options,
                RunCallbacks on, const std::function<void(JobFrame&)>& reported = {});

/// A frame's report as the job reports list it (docs/JSON.md `frames[k]`).
nlohmann::json frame_json(const JobFrame& f);
/// A method's run: method, plan, frames, valid, error.
nlohmann::json run_json(const MethodRun& r);

}  // namespace dgwarp
