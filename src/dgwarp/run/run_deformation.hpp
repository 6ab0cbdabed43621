#pragma once
// A deformation run: every frame of a motion, one after the other, each
// stepped from the original mesh, repaired and measured (deform_frame.hpp).
// The library never writes files: each frame's coordinates and report go to
// the caller's `frame_done`, which writes them (the CLI), hands them to a
// solver, or keeps them (Python).
//
//   const Deformation d = prepare_deformation(mesh, spec, Method::dg_harmonic);
//   RunCallbacks on;
//   on.frame_done = [&](const FrameView& f) { write(f.points); return f.report.valid(); };
//   const RunReport r = run_frames(RunContext::of(mesh, spec, d), {}, on);
#include <cstdint>
#include <functional>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "dgwarp/core/progress.hpp"
#include "dgwarp/mesh/mesh.hpp"
#include "dgwarp/methods/method.hpp"
#include "dgwarp/motion/motion_spec.hpp"
#include "dgwarp/motion/resolve_motion.hpp"
#include "dgwarp/run/deform_frame.hpp"
#include "dgwarp/run/original_cells.hpp"
#include "dgwarp/run/slide_pass.hpp"

namespace dgwarp {

/// What every frame of one (mesh, motion, method) reuses, built once.
struct Deformation {
    Method method = Method::dg_harmonic;
    MethodOptions options;
    ResolvedBoundary boundary;
    OriginalCells original;
    Plan plan;
    std::optional<SlidePass> slide;  // with sliding markers: their first pass (slide_pass.hpp)
    /// original_seconds: the original's measure, done beside the prepare on
    /// a thread of its own (run_beside), so the two overlap.
    double resolve_seconds = 0, original_seconds = 0, prepare_seconds = 0;
};

/// `method`'s plan for frames of `mesh`: prepare with the mesh's cells,
/// except that DG-harmonic's guard is a frame guard (make_frame_guard):
/// step_frame judges each one pass on the frame's measure and builds
/// laplacian's plan on the run's mesh, so the guard keeps no copy of the
/// cells and no measure of its own. Throws as prepare does.
Plan prepare_for_frames(Method method, const Mesh& mesh, const BoundarySet& boundary,
                        const MethodOptions& options = {}, const ProgressFn& progress = {});

/// The same guard on a DG-harmonic plan read from a file (a plan file keeps
/// the plan's arrays, not the guard); other plans, and meshes without cells,
/// are left as they are.
void attach_frame_guard(Plan& plan, const Mesh& mesh, const BoundarySet& boundary, const MethodOptions& options);

/// Resolves `spec`'s boundary on `mesh` (resolve_boundary: throws MeshError
/// naming the marker or node), measures the original cells and prepares
/// `method`'s plan with the mesh's cells. Throws as prepare does.
Deformation prepare_deformation(const Mesh& mesh, const MotionSpec& spec, Method method,
                                const MethodOptions& options = {}, const ProgressFn& progress = {});

/// What run_frames reads; nothing is copied (every reference must outlive the run).
struct RunContext {
    const Mesh& mesh;
    const MotionSpec& spec;
    const ResolvedBoundary& boundary;
    const OriginalCells& original;
    const Plan& plan;
    const MethodOptions& options;      // the plan's (a loaded plan's own)
    const SlidePass* slide = nullptr;  // with sliding markers: their first pass

    static RunContext of(const Mesh& mesh, const MotionSpec& spec, const Deformation& d) {
        return {mesh, spec, d.boundary, d.original, d.plan, d.options, d.slide ? &*d.slide : nullptr};
    }
};

struct RunOptions {
    FrameOptions frame;
    bool stop_at_invalid = true;  // no frame after one with cells the motion inverted
};

/// One finished frame, as frame_done sees it (valid during the call only).
struct FrameView {
    std::size_t frame = 0;
    double time = 0;                   // frame_time(spec, frame)
    const ResolvedFrame& motion;       // its boundary motion and the motion's warnings
    std::span<const double> points;    // its coordinates, num_points × dim
    const FrameReport& report;
    const FrameCells& cells;
    /// The array `points` views, lent to the call: it may swap it out and
    /// back (e.g. into a Mesh, to write the frame without a copy of its
    /// coordinates) as long as it holds the same values when it returns.
    std::vector<double>& points_array;
};

struct RunCallbacks {
    /// Before frame k's step; returns the step's progress function (or an empty one).
    std::function<ProgressFn(std::size_t frame)> frame_started;
    /// When frame k's repair starts (it may take seconds).
    std::function<void(std::size_t frame)> repair_started;
    /// The step, when not the plan's own deform (e.g. a plan spread over MPI
    /// processes): fills `out` and returns the step's report.
    std::function<StepReport(const ResolvedFrame& motion, std::span<double> out, const ProgressFn& progress)> step;
    /// Called with true right before a frame's step (the plan's deform and
    /// DG-harmonic's guard, or `step`) and with false right after it, e.g. to
    /// tell a step's errors from the others (resolving the frame's motion,
    /// writing it).
    std::function<void(bool)> step_running;
    /// Each finished frame, valid or not; false stops the run.
    std::function<bool(const FrameView&)> frame_done;
};

struct RunReport {
    std::vector<FrameReport> frames;  // the frames run, in order
    /// The first frame with cells the motion inverted, or -1.
    std::int64_t first_invalid = -1;
    bool valid() const { return first_invalid < 0; }
};

/// Every frame of ctx.spec in order (or until frame_done returns false, or
/// after an invalid frame when options.stop_at_invalid). Throws what a step
/// or resolve_frame throws; the frames before were handed to frame_done.
RunReport run_frames(const RunContext& ctx, const RunOptions& options, const RunCallbacks& callbacks);

}  // namespace dgwarp
