// part_run.hpp: run_frames' loop, each frame's figures reduced over the parts.
#include "dgwarp/mpi/part_run.hpp"

#include <tuple>

#include "dgwarp/core/stopwatch.hpp"
#include "dgwarp/mpi/agreement.hpp"
#include "dgwarp/mpi/part_reductions.hpp"
#include "dgwarp/mpi/part_repair.hpp"
#include "dgwarp/mpi/reductions.hpp"
#include "dgwarp/quality/mesh_quality.hpp"
#include "dgwarp/run/deform_frame.hpp"

namespace dgwarp::mpi {

RunReport run_frames_on_parts(const PartRunContext& ctx, const RunOptions& options, const PartRunCallbacks& callbacks) {
    const MPI_Comm comm = ctx.comm;
    const std::vector<std::int64_t> ids(ctx.cell_ids.begin(), ctx.cell_ids.end());
    RunReport run;
    const std::size_t frames = frame_count(ctx.spec);
    std::vector<double> points(ctx.mesh.points.size());
    // Every process alike (a part may have no node): the ids given for every node everywhere.
    const bool ids_given = min(comm, std::int64_t{ctx.node_ids.size() == ctx.mesh.num_points() &&
                                                  (!ctx.node_ids.empty() || ctx.mesh.num_points() == 0)}) == 1 &&
                           max(comm, static_cast<std::int64_t>(ctx.node_ids.size())) > 0;
    const bool last_resort = options.frame.repair == Repair::method_default && ids_given &&
                             plan_method(ctx.plan.plan.plan) == Method::dg_harmonic;
    for (std::size_t k = 0; k < frames; ++k) {
        collectively(comm, [&] {
            if (callbacks.frame_started) callbacks.frame_started(k);
        });
        ResolvedFrame motion;
        collectively(comm, [&] { motion = resolve_frame(ctx.mesh, ctx.spec, ctx.boundary, k); });
        FrameReport report;
        std::vector<double> process_seconds;
        Stopwatch sw;
        report.step = deform_part(ctx.plan, ctx.mesh.points, motion.motion, points, process_seconds);
        report.step_seconds = sw.lap();

        // The frame's cells here, their figures over every process.
        FrameCells cells;
        collectively(comm, [&] { cells = measure_frame(ctx.mesh, points, ctx.original, ctx.boundary.boundary.nodes); });
        if (last_resort) {
            // DG-harmonic's last resort, as finish_frame runs it on one process (run/deform_frame.hpp).
            Stopwatch repair;
            report.untangled = last_resort_over_parts(comm, ctx.mesh, ctx.original.own_orientation, ctx.node_ids,
                                                      ctx.cell_ids, ctx.boundary.boundary.nodes, cells.inverted, points);
            if (report.untangled) {
                report.last_resort = true;
                collectively(comm, [&] { cells = measure_frame(ctx.mesh, points, ctx.original, ctx.boundary.boundary.nodes); });
            }
            report.repair_seconds = repair.lap();
        }
        report.quality = quality_over_parts(comm, cells.quality, ids);
        report.ratio = ratios_over_parts(comm, quality_ratios(cells.quality, ctx.original.quality), ids);
        const std::size_t worst = options.frame.worst_count;
        std::tie(report.worst_inverted, report.inverted_by_motion) =
            worst_over_parts(comm, cells.inverted, cells.quality, ids, worst);
        std::tie(report.worst_on_boundary, report.inverted_on_boundary) =
            worst_over_parts(comm, cells.inverted_on_boundary, cells.quality, ids, worst);
        report.warnings = warnings_over_parts(comm, frame_warnings(motion, report.step));
        report.quality_seconds = sw.lap() - report.repair_seconds;

        const bool valid = report.valid();  // the same on every process (reduced counts)
        if (!valid && run.first_invalid < 0) run.first_invalid = static_cast<std::int64_t>(k);
        run.frames.push_back(report);
        bool go_on = true;
        collectively(comm, [&] {
            if (callbacks.frame_done)
                go_on = callbacks.frame_done(PartFrameView{k, frame_time(ctx.spec, k), motion, points,
                                                           run.frames.back(), cells, process_seconds});
        });
        go_on = min(comm, std::int64_t{go_on ? 1 : 0}) == 1;
        if (!go_on || (!valid && options.stop_at_invalid)) break;
    }
    return run;
}

}  // namespace dgwarp::mpi
