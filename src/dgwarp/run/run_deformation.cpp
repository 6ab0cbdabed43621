#include "dgwarp/run/run_deformation.hpp"

#include <utility>

#include "dgwarp/core/stopwatch.hpp"

namespace dgwarp {

Deformation prepare_deformation(const Mesh& mesh, const MotionSpec& spec, Method method, const MethodOptions& options,
                                const ProgressFn& progress) {
    Deformation d;
    d.method = method;
    d.options = options;
    Stopwatch sw;
    d.boundary = resolve_boundary(mesh, spec);
    d.resolve_seconds = sw.lap();
    d.original = measure_original(mesh);
    d.original_seconds = sw.lap();
    d.plan = prepare(method, mesh.dim, mesh.points, mesh.cells, d.boundary.boundary, options, progress);
    d.prepare_seconds = sw.lap();
    return d;
}

RunReport run_frames(const RunContext& ctx, const RunOptions& options, const RunCallbacks& callbacks) {
    RunReport run;
    const std::size_t frames = frame_count(ctx.spec);
    const Method method = plan_method(ctx.plan);
    std::vector<double> points(ctx.mesh.points.size());
    for (std::size_t k = 0; k < frames; ++k) {
        const ProgressFn progress = callbacks.frame_started ? callbacks.frame_started(k) : ProgressFn{};
        const ResolvedFrame motion = resolve_frame(ctx.mesh, ctx.spec, ctx.boundary, k);
        FrameReport report;
        Stopwatch sw;
        if (callbacks.step)
            report.step = callbacks.step(motion, points, progress);
        else
            report.step = deform(ctx.plan, ctx.mesh.points, motion.motion, points,
                                 step_options(ctx.options, motion.folded_faces), progress);
        report.step_seconds = sw.lap();
        report.warnings = frame_warnings(motion, report.step);
        const FrameCells cells =
            finish_frame(method, ctx.mesh, ctx.original, ctx.boundary.boundary.nodes, options.frame, points, report,
                         callbacks.repair_started ? [&] { callbacks.repair_started(k); } : RepairStarted{});
        const bool valid = report.valid();
        if (!valid && run.first_invalid < 0) run.first_invalid = static_cast<std::int64_t>(k);
        run.frames.push_back(report);
        const bool go_on =
            !callbacks.frame_done ||
            callbacks.frame_done(FrameView{k, frame_time(ctx.spec, k), motion, points, run.frames.back(), cells});
        if (!go_on || (!valid && options.stop_at_invalid)) break;
    }
    return run;
}

}  // namespace dgwarp
