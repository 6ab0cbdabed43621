#include "dgwarp/job/method_run.hpp"

#include "dgwarp/core/error.hpp"
#include "dgwarp/core/stopwatch.hpp"
#include "dgwarp/run/report_json.hpp"

namespace dgwarp {

std::string cell_list(const std::vector<std::int64_t>& cells) {
    std::string s;
    for (auto c : cells) s += (s.empty() ? "" : ", ") + std::to_string(c);
    return s;
}

std::string invalid_frame_error(const JobFrame& bad) {
    std::string e = std::to_string(bad.inverted_by_motion) + " inverted cell" + (bad.inverted_by_motion == 1 ? "" : "s") +
                    " in frame " + std::to_string(bad.frame) + " (worst: " + cell_list(bad.worst_inverted) + ")";
    if (bad.inverted_on_boundary > 0)
        e += "; " + std::to_string(bad.inverted_on_boundary) + " of them ha" + (bad.inverted_on_boundary == 1 ? "s" : "ve") +
             " every node on the boundary (worst: " + cell_list(bad.worst_on_boundary) +
             "): the boundary motion itself folds them, which no method can repair; check the "
             "motion (nodes a moving marker shares with a static one follow the moving one)";
    return e;
}

bool add_frame(MethodRun& run, JobFrame f, bool write_invalid) {
    const bool invalid = f.inverted_by_motion > 0;
    run.frames.push_back(std::move(f));
    if (!invalid) return true;
    run.invalid = true;
    run.error = invalid_frame_error(run.frames.back());
    return write_invalid;
}

void run_method(JobInputs& in, MethodRun& run, FrameOutputs& outputs, const MethodRunOptions& options,
                RunCallbacks on, const std::function<void(JobFrame&)>& reported) {
    RunOptions run_options;
    run_options.frame = options.frame;
    run_options.stop_at_invalid = false;  // add_frame decides, with write_invalid
    // Errors of a step may end this method's run; errors anywhere else
    // (reading a frame's motion, writing) end the job.
    bool in_step = false;
    on.step_running = [&in_step, caller = std::move(on.step_running)](bool running) {
        in_step = running;
        if (caller) caller(running);
    };
    on.frame_done = [&](const FrameView& v) {
        JobFrame f;
        static_cast<FrameReport&>(f) = v.report;
        f.frame = v.frame;
        f.time = v.time;
        if (f.valid() || options.write_invalid) {
            Stopwatch sw;
            f.output = write_frame(in, outputs, v.frame, v.points_array, v.cells.quality).string();
            f.write_seconds = sw.lap();
        }
        if (reported) reported(f);
        return add_frame(run, std::move(f), options.write_invalid);
    };
    const JobPlan& p = run.planned;
    try {
        run_frames(RunContext{in.mesh, in.spec, in.boundary, in.original, p.plan, p.options, p.slide ? &*p.slide : nullptr},
                   run_options, on);
    } catch (const InvalidResultError& e) {
        if (!options.keep_step_errors || !in_step) throw;
        run.error = e.what();
        run.invalid = true;
    } catch (const Error& e) {
        if (!options.keep_step_errors || !in_step) throw;
        run.error = e.what();
        run.invalid = run.failed = true;
    }
}

nlohmann::json frame_json(const JobFrame& f) {
    nlohmann::json j = {{"frame", f.frame},
                        {"time", f.time},
                        {"output", f.output.empty() ? nlohmann::json(nullptr) : nlohmann::json(f.output)}};
    j.update(frame_report_json(f));
    j["seconds"]["write"] = f.write_seconds;
    if (!f.process_seconds.empty()) j["process_seconds"] = f.process_seconds;
    return j;
}

nlohmann::json run_json(const MethodRun& r) {
    nlohmann::json j = {{"method", method_name(r.planned.method)}, {"plan", plan_json(r.planned)},
                        {"frames", nlohmann::json::array()}, {"valid", !r.invalid},
                        {"error", r.error.empty() ? nlohmann::json(nullptr) : nlohmann::json(r.error)}};
    for (const auto& f : r.frames) j["frames"].push_back(frame_json(f));
    return j;
}

}  // namespace dgwarp
