#include "dgwarp/run/run_deformation.hpp"

#include <utility>

#include "dgwarp/core/stopwatch.hpp"
#include "dgwarp/methods/dg_harmonic_guard.hpp"

namespace dgwarp {

Plan prepare_for_frames(Method method, const Mesh& mesh, const BoundarySet& boundary, const MethodOptions& options,
                        const ProgressFn& progress) {
    if (method != Method::dg_harmonic || mesh.cells.empty())
        return prepare(method, mesh.dim, mesh.points, mesh.cells, boundary, options, progress);
    Plan plan = prepare(method, mesh.dim, mesh.points, boundary, options, progress);
    Stopwatch sw;
    attach_frame_guard(plan, mesh, boundary, options);
    std::get<DgHarmonicPlan>(plan).stats.guard_seconds = sw.lap();
    return plan;
}

void attach_frame_guard(Plan& plan, const Mesh& mesh, const BoundarySet& boundary, const MethodOptions& options) {
    auto* h = std::get_if<DgHarmonicPlan>(&plan);
    if (!h || mesh.cells.empty()) return;
    h->guard = make_frame_guard(mesh.dim, mesh.points, mesh.cells, boundary,
                                guard_laplacian_options(options.laplacian, options.dg_harmonic));
}

Deformation prepare_deformation(const Mesh& mesh, const MotionSpec& spec, Method method, const MethodOptions& options,
                                const ProgressFn& progress) {
    Deformation d;
    d.method = method;
    d.options = options;
    Stopwatch sw;
    d.boundary = resolve_boundary(mesh, spec);
    d.resolve_seconds = sw.lap();
    // The original's measure beside the prepare (mostly serial: a
    // triangulation, a factorisation), on a thread of its own.
    d.original = measure_original_beside(
        mesh,
        [&] {
            d.plan = prepare_for_frames(method, mesh, d.boundary.boundary, options, progress);
            if (!d.boundary.slides.empty()) d.slide = prepare_slide_pass(mesh, d.boundary, options);
            d.prepare_seconds = sw.lap();
        },
        &d.original_seconds);
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
        std::optional<FrameCells> stepped;
        if (callbacks.step_running) callbacks.step_running(true);
        if (callbacks.step) {
            Stopwatch sw;
            if (ctx.slide) {
                // The sliding nodes' first pass here, the step wherever `step` runs it.
                ResolvedFrame slid = motion;
                slide_motion(*ctx.slide, slid.motion);
                report.step = callbacks.step(slid, points, progress);
                apply_slides(ctx.slide->slides, ctx.mesh.dim, points);
            } else {
                report.step = callbacks.step(motion, points, progress);
            }
            report.step_seconds = sw.lap();
        } else {
            stepped = step_frame(ctx.plan, ctx.mesh, ctx.original, ctx.boundary.boundary.nodes, ctx.slide,
                                 motion.motion, step_options(ctx.options, motion.folded_faces), points, report,
                                 progress);
        }
        if (callbacks.step_running) callbacks.step_running(false);
        report.warnings = frame_warnings(motion, report.step);
        const FrameCells cells =
            finish_frame(method, ctx.mesh, ctx.original, ctx.boundary.boundary.nodes, options.frame, points, report,
                         callbacks.repair_started ? [&] { callbacks.repair_started(k); } : RepairStarted{},
                         std::move(stepped));
        const bool valid = report.valid();
        if (!valid && run.first_invalid < 0) run.first_invalid = static_cast<std::int64_t>(k);
        run.frames.push_back(report);
        const bool go_on =
            !callbacks.frame_done ||
            callbacks.frame_done(
                FrameView{k, frame_time(ctx.spec, k), motion, points, run.frames.back(), cells, points});
        if (!go_on || (!valid && options.stop_at_invalid)) break;
    }
    return run;
}

}  // namespace dgwarp
