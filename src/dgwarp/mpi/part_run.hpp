#pragma once
// A deformation run when each process holds its own part of the mesh (a
// decomposed case, a solver's partition): every frame resolved, stepped with
// the distributed plan and measured on each process, its report reduced over
// the processes (part_reductions.hpp), as run_frames (run/run_deformation.hpp)
// does on one process over the whole mesh. Collective: every process of
// ctx.comm calls it; a failure on one (its motion, its step, its frame_done)
// is raised on every process (agreement.hpp). The repair that runs is
// dg-harmonic's last resort (options.frame.repair method_default, given the
// nodes' ids: part_repair.hpp), not Repair::untangle.
//
//   const PartRunContext ctx{comm, part_mesh, spec, boundary, original, plan, cell_ids};
//   PartRunCallbacks on;
//   on.frame_done = [&](const PartFrameView& f) { write_my_part(f.points); return true; };
//   const RunReport r = run_frames_on_parts(ctx, {}, on);
#include <mpi.h>

#include <cstdint>
#include <functional>
#include <span>
#include <vector>

#include "dgwarp/mesh/mesh.hpp"
#include "dgwarp/motion/motion_spec.hpp"
#include "dgwarp/motion/resolve_motion.hpp"
#include "dgwarp/mpi/root_session.hpp"
#include "dgwarp/run/original_cells.hpp"
#include "dgwarp/run/run_deformation.hpp"

namespace dgwarp::mpi {

/// What run_frames_on_parts reads; nothing is copied.
struct PartRunContext {
    MPI_Comm comm;
    const Mesh& mesh;                       // this process's part
    const MotionSpec& spec;
    const ResolvedBoundary& boundary;       // resolved on the part (share_interface_markers first)
    const OriginalCells& original;          // its cells, judged by dominant_orientations_over_parts
    const PartPlan& plan;                   // prepare_part over the part's nodes
    std::span<const std::int64_t> cell_ids;  // per local cell, its id in the whole mesh
    /// Per local node, its id in the whole mesh (the prepare's global ids):
    /// with them, dg-harmonic's last resort runs over the parts
    /// (part_repair.hpp); without, no repair runs.
    std::span<const std::int64_t> node_ids = {};
};

/// One finished frame, as frame_done sees it on every process.
struct PartFrameView {
    std::size_t frame = 0;
    double time = 0;
    const ResolvedFrame& motion;           // this process's boundary motion
    std::span<const double> points;        // this process's coordinates of the frame
    /// Over every process: quality, ratios, the inverted cells (whole-mesh
    /// ids) and their counts; warnings on rank 0 (warnings_over_parts).
    const FrameReport& report;
    const FrameCells& cells;               // this process's cells
    const std::vector<double>& process_seconds;  // on rank 0: each process's step time
};

struct PartRunCallbacks {
    /// Before frame k's step, on every process.
    std::function<void(std::size_t frame)> frame_started;
    /// Each frame, on every process (each writes its part); false on any
    /// process stops the run on all; an exception on one is raised on all.
    std::function<bool(const PartFrameView&)> frame_done;
};

/// Every frame of ctx.spec in order (or until frame_done returns false, or
/// after an invalid frame when options.stop_at_invalid; options.frame's
/// repair is not run). The reports are the reduced ones, alike on every
/// process but for the warnings (rank 0's). Throws on every process alike.
RunReport run_frames_on_parts(const PartRunContext& ctx, const RunOptions& options, const PartRunCallbacks& callbacks);

}  // namespace dgwarp::mpi
