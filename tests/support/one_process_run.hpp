#pragma once
// One process's run over a whole mesh (run/run_deformation.hpp), every
// frame's coordinates kept: what the MPI tests compare each process's part with.
#include <vector>

#include "dgwarp/run/run_deformation.hpp"

namespace dgwarp::test {

struct OneProcessRun {
    RunReport report;
    std::vector<std::vector<double>> points;  // per frame, num_points × dim
};

inline OneProcessRun one_process_run(const Mesh& mesh, const MotionSpec& spec, Method method,
                                     const MethodOptions& options = {}) {
    const Deformation d = prepare_deformation(mesh, spec, method, options);
    OneProcessRun one;
    RunCallbacks keep;
    keep.frame_done = [&](const FrameView& f) {
        one.points.emplace_back(f.points.begin(), f.points.end());
        return true;
    };
    one.report = run_frames(RunContext::of(mesh, spec, d), {}, keep);
    return one;
}

}  // namespace dgwarp::test
