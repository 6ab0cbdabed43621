#pragma once
// One frame of a run: the method's step, the repair (dg-harmonic's last
// resort, or untangling when asked), and the frame's quality against the
// original mesh's. What `dgwarp deform`, the Python package and a solver
// calling the library do after every step, in one place (docs/API.md).
#include <cstdint>
#include <functional>
#include <optional>
#include <span>
#include <vector>

#include "dgwarp/mesh/mesh.hpp"
#include "dgwarp/methods/dg_harmonic_guard.hpp"
#include "dgwarp/methods/method.hpp"
#include "dgwarp/motion/resolve_motion.hpp"
#include "dgwarp/quality/mesh_quality.hpp"
#include "dgwarp/repair/untangle.hpp"
#include "dgwarp/run/original_cells.hpp"
#include "dgwarp/run/slide_pass.hpp"

namespace dgwarp {

/// What runs after a step.
enum class Repair {
    method_default,  // dg-harmonic: its last resort repairs the cells its step inverted; the others: nothing
    untangle,        // untangle every cell at or below FrameOptions::untangle_target (`dgwarp deform --untangle`)
    none,            // no repair (`--no-untangle`)
};

struct FrameOptions {
    Repair repair = Repair::method_default;
    double untangle_target = UntangleOptions{}.target_quality;  // with Repair::untangle
    std::size_t worst_count = 10;                               // cells listed in worst_inverted and worst_on_boundary
};

/// Per cell of a frame: its quality and ratio to the original's, and the cells the run inverted.
struct FrameCells {
    /// Judged by the original's orientation (OriginalCells::orientation). The
    /// ratios to the original's, where wanted, are quality_ratios(quality,
    /// original.quality): not kept, a mesh of 5M cells would hold 40 MB more.
    std::vector<double> quality;
    /// Cells valid in the original and inverted now (newly_inverted_cells):
    /// what makes a frame invalid; cells already inverted in the input are not the motion's doing.
    std::vector<std::int64_t> inverted;
    /// Of those, the cells whose every node is on the boundary: the boundary
    /// motion alone inverts them, and nothing that moves volume nodes can help.
    std::vector<std::int64_t> inverted_on_boundary;
};

/// What one frame did: plain data a report (text, JSON, Python) is made from.
struct FrameReport {
    StepReport step;
    std::optional<UntangleReport> untangled;  // when a repair found cells to mend
    bool last_resort = false;                 // the repair was dg-harmonic's last resort, not Repair::untangle
    QualitySummary quality;
    RatioSummary ratio;
    std::int64_t inverted_by_motion = 0;          // FrameCells::inverted's size
    std::vector<std::int64_t> worst_inverted;     // the worst of those (up to FrameOptions::worst_count)
    std::int64_t inverted_on_boundary = 0;        // FrameCells::inverted_on_boundary's size
    std::vector<std::int64_t> worst_on_boundary;  // the worst of those
    std::vector<Warning> warnings;                // the frame's motion's, then its step's (frame_warnings)
    double step_seconds = 0, repair_seconds = 0, quality_seconds = 0;

    bool valid() const { return inverted_by_motion == 0; }
};

/// The options of a frame's step: DG-harmonic's guard off when the boundary
/// motion itself turns `folded_faces` faces over (ResolvedFrame::folded_faces):
/// no redo of the volume can mend their cells.
MethodOptions step_options(MethodOptions options, std::int64_t folded_faces);

/// Warnings about a step's report: boundary nodes at the same coordinates
/// that were given different motions (WarningCode::conflicting_shared_motions).
std::vector<Warning> step_warnings(const StepReport& step);

/// A frame's warnings: its motion's (ResolvedFrame::warnings), then its step's.
std::vector<Warning> frame_warnings(const ResolvedFrame& motion, const StepReport& step);

/// Up to `count` of `cells`, those of smallest `quality` first (stable: the lower index first on ties).
std::vector<std::int64_t> worst_cells(std::vector<std::int64_t> cells, std::span<const double> quality,
                                      std::size_t count);

/// The cells of `mesh` at `points` (num_points × dim) against the original's.
/// `fixed`: the boundary nodes (BoundarySet::nodes, sorted). Threaded.
FrameCells measure_frame(const Mesh& mesh, std::span<const double> points, const OriginalCells& original,
                         std::span<const NodeId> fixed);

/// What DG-harmonic's guard reads of a frame's cells (its GuardMeasure): the
/// cells the motion inverted, those of them with only boundary nodes, and the
/// lowest quality of the cells valid in the original (a NaN counts as -1).
GuardMeasure guard_measure_of(const FrameCells& cells, const OriginalCells& original);

/// Whether step_frame measures `plan`'s step with DG-harmonic's guard (a
/// DG-harmonic plan with a guard, and options.dg_harmonic.redo_below not negative).
bool guards_frames(const Plan& plan, const MethodOptions& options);

/// A frame's step: deform with DG-harmonic's guard off; then, when `plan` is
/// DG-harmonic's with a guard and options.dg_harmonic.redo_below is not
/// negative (step_options turns it off where the boundary motion folds
/// faces), the guard judges the one pass on the frame's own measure
/// (measure_frame: the one every frame has, so a frame is measured once) and
/// a one pass below its bar (redo_below × original.valid_min) or folded is
/// solved again by the laplacian reference, the better result kept
/// (dg_harmonic_guard.hpp; report.step.guard says what it did,
/// report.step.substeps laplacian's increments when its result is kept).
/// Adds to report's step_seconds (the one pass and any redo) and
/// quality_seconds (the measure); sets report.step. Returns the cells of
/// `out` as it is on return when they were measured (pass them to
/// finish_frame), nullopt otherwise. `fixed`: the boundary nodes (sorted).
/// `slide`: with sliding markers, their first pass (slide_pass.hpp), which
/// gives their nodes' motion before the step (`motion`'s entries for them
/// are ignored) and puts them back into their planes after it; else null.
std::optional<FrameCells> step_frame(const Plan& plan, const Mesh& mesh, const OriginalCells& original,
                                     std::span<const NodeId> fixed, const SlidePass* slide,
                                     const BoundaryMotion& motion, const MethodOptions& options,
                                     std::span<double> out, FrameReport& report, const ProgressFn& progress = {});

/// Called when a repair starts (for a progress display: it may take seconds).
using RepairStarted = std::function<void()>;

/// After a step of `method` moved `points` (changed in place): the repair
/// `options` ask for, then the frame's cells (returned) and report's
/// untangled, last_resort, quality, ratio, inverted and worst fields, and
/// its repair and quality seconds. `fixed`: the boundary nodes (sorted).
/// `measured`: the cells of `points` as they are, when the step measured
/// them (step_frame): not measured again.
FrameCells finish_frame(Method method, const Mesh& mesh, const OriginalCells& original, std::span<const NodeId> fixed,
                        const FrameOptions& options, std::span<double> points, FrameReport& report,
                        const RepairStarted& repair_started = {}, std::optional<FrameCells> measured = std::nullopt);

/// One frame: step_frame (deform(plan, mesh.points, motion.motion, out,
/// step_options(...)) and DG-harmonic's guard), then finish_frame; the report's warnings are frame_warnings'. `out`: num_points × dim, the frame's coordinates
/// (measured from the original mesh, not the previous frame). `cells`, when
/// not null, receives the frame's cells. Throws as deform does.
FrameReport deform_frame(const Plan& plan, const Mesh& mesh, const OriginalCells& original,
                         const ResolvedBoundary& boundary, const ResolvedFrame& motion, const MethodOptions& options,
                         const FrameOptions& frame_options, std::span<double> out, FrameCells* cells = nullptr,
                         const ProgressFn& progress = {}, const SlidePass* slide = nullptr);

}  // namespace dgwarp
