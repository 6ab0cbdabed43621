#pragma once
// DG-harmonic's guard (docs/dg-harmonic.md, "The guard"): when the plan was
// prepared with the mesh's cells, every step's result is measured (Knupp's
// shape quality of every cell, as `dgwarp quality` computes it). A step that
// inverts a cell, or whose minimum quality falls below redo_below × the
// original mesh's, is solved again by the laplacian reference (stiffened
// elasticity in increments, methods/laplacian.hpp) and the better of the two
// results is kept: fewer inverted cells first, then the higher minimum. A
// step whose boundary motion itself folds cells (every node of an inverted
// cell on the boundary) is not redone: no volume method can mend it.
// Frames the one pass handles stay one pass (plus the measurement); the
// others cost a laplacian solve, and the step's report says so.
#include <cstdint>
#include <memory>
#include <mutex>
#include <span>
#include <string>
#include <vector>

#include "dgwarp/core/progress.hpp"
#include "dgwarp/mesh/mesh.hpp"
#include "dgwarp/methods/laplacian.hpp"
#include "dgwarp/motion/node_motion.hpp"

namespace dgwarp {

struct DgHarmonicPlan;
struct DgHarmonicOptions;

/// What the guard keeps: the cells and their original orientations and
/// quality, and what builds the laplacian plan that solves a step again (on
/// the first step that needs it: prepare stays cheap).
struct DgHarmonicGuard {
    Mesh mesh;                               // dim, the original points and the cells (no markers)
    BoundarySet boundary;                    // the plan's
    LaplacianOptions laplacian_options;
    /// A guard for frames (make_frame_guard): no cells and no measure of
    /// its own. The run layer (run/deform_frame.hpp's step_frame) judges the
    /// one pass on the frame's measure and gives laplacian's plan the run's
    /// mesh; a bare deform() steps such a plan's one pass unchecked.
    bool for_frames = false;
    std::vector<std::int8_t> orientations;   // dominant_orientations(mesh)
    /// Per cell: 0 not judged (inverted or flat in the original), 1 judged,
    /// 2 judged and every node a boundary node (the boundary motion alone
    /// places it: no volume method changes it).
    std::vector<std::uint8_t> judged;
    double original_min = 0;                 // the minimum quality of the judged cells in the original
    /// The measure's layout (built from `judged`). The guard numbers the
    /// nodes its own way, along a Morton curve: local node k is mesh node
    /// local_order[k], and each measure first copies the points into that
    /// order (one pass over the nodes). The judged simplices (triangles in
    /// 2D, tetrahedra in 3D) hold local node ids and are grouped by the
    /// local id of their first node, 512 ids to a group (a counting sort:
    /// one pass, stable), so that a pass over them reads the points of a few
    /// hundred neighbouring nodes at a time, from L1 and L2, whatever the
    /// mesh's numbering; per simplex its orientation times `judged` (±1, or
    /// ±2 when every node is a boundary node). Judged cells of other types
    /// are measured by index, on the mesh's numbering.
    std::vector<NodeId> local_order;         // num_points: Morton order of the nodes
    std::vector<NodeId> simplex_nodes;       // (dim + 1) per simplex, local node ids
    std::vector<std::int8_t> simplex_flags;  // orientation × judged
    std::vector<std::int64_t> other_cells;   // ascending
    // Built once, by the first step that is solved again (laplacian_plan_of).
    mutable std::once_flag laplacian_once;
    mutable LaplacianPlan laplacian;
};

/// The guard's laplacian plan, built on the first call (thread-safe) on the
/// original `points` and the `cells`: the guard's own, or for a frame guard
/// the run's mesh's.
const LaplacianPlan& laplacian_plan_of(const DgHarmonicGuard& guard, std::span<const double> points,
                                       const ElementList& cells);

/// The guard of a mesh: `points` num_points × dim (the original), `cells`
/// the mesh's cells, `boundary` the plan's boundary set. Throws as
/// check_laplacian_cells does (MeshError for cells of another dimension or
/// out of range).
std::shared_ptr<const DgHarmonicGuard> make_dg_harmonic_guard(int dim, std::span<const double> points,
                                                              const ElementList& cells, const BoundarySet& boundary,
                                                              const LaplacianOptions& laplacian = {});

/// A guard for frames (DgHarmonicGuard::for_frames): checks `cells` as
/// make_dg_harmonic_guard does and keeps neither them nor a measure (the
/// run has the mesh, and measures each frame anyway: 0.5-0.7 s of prepare
/// and 130 MB less at 865k nodes).
std::shared_ptr<const DgHarmonicGuard> make_frame_guard(int dim, std::span<const double> points,
                                                        const ElementList& cells, const BoundarySet& boundary,
                                                        const LaplacianOptions& laplacian = {});

/// The laplacian options of the guard: `laplacian` with its increments
/// doubled at most up to harmonic.redo_max_increments.
LaplacianOptions guard_laplacian_options(const LaplacianOptions& laplacian, const DgHarmonicOptions& harmonic);

/// The guard's measure of one result: the judged cells it inverts and the
/// minimum quality of the judged cells (the value cell_shape_quality gives).
/// One pass over the cells, threaded; triangles and tetrahedra by a
/// vectorised kernel without the generic dispatch (guard_kernel.hpp: the
/// minimum is found on the cube of the metric, with no cube root per cell).
struct GuardMeasure {
    std::int64_t inverted = 0;
    std::int64_t inverted_on_boundary = 0;  // of those, the cells whose every node is a boundary node
    double min_quality = 0;
};
GuardMeasure measure_for_guard(const DgHarmonicGuard& guard, std::span<const double> points);

/// What a guarded step did.
struct DgHarmonicGuardReport {
    std::int64_t conflicting_shared_vertices = 0;  // as DgHarmonicStepReport (the one pass)
    bool checked = false;        // the result was measured (the plan has a guard and redo_below >= 0)
    GuardMeasure one_pass;       // the one pass's measure (when checked)
    double bar = 0;              // redo_below × the original minimum quality (when checked)
    double measure_seconds = 0;  // the time the one pass's measure took (when checked)
    bool redone = false;         // the one pass fell below the bar: laplacian solved the step again
    /// Not redone although the one pass folds: the boundary motion itself
    /// folds cells (one_pass.inverted_on_boundary > 0), which no volume
    /// method can change.
    bool boundary_folds = false;
    bool kept_redo = false;      // the laplacian result was better and is the one written
    int increments = 0;          // laplacian's increments (when redone)
    GuardMeasure redo;           // laplacian's measure (when redone and its solve succeeded)
    /// Why laplacian's solve failed (redone) or was not tried although the
    /// step is below the bar (not redone: a 3D mesh above redo_max_nodes_3d);
    /// the one pass is kept.
    std::string redo_error;
    double redo_seconds = 0;     // the time laplacian's solve and measure took
};

/// DG-harmonic's step with its guard (deform_dg_harmonic when the plan has
/// none or `redo_below` is negative). `redo_below`: the bar, a fraction of
/// the original minimum quality (0: only a step that inverts a cell is
/// redone; negative: never measured). `out` num_points × dim (may alias
/// points).
DgHarmonicGuardReport deform_dg_harmonic_guarded(const DgHarmonicPlan& plan, std::span<const double> points,
                                                 const BoundaryMotion& motion, std::span<double> out,
                                                 double redo_below, const ProgressFn& progress = {});

/// The original points a step's redo needs, when the step writes `out`:
/// `points` itself, or a copy of them in `kept` when `out` overlaps them (a
/// step in place).
std::span<const double> points_kept_from(std::span<const double> points, std::span<const double> out,
                                         std::vector<double>& kept);

/// The guard's pieces, for a caller that measures the one pass itself: the
/// run layer (run/deform_frame.hpp) measures every frame anyway, so there the
/// guard judges the one pass on that measure and a frame is measured once.
/// deform_dg_harmonic_guarded is the same sequence on the guard's own measure.
///
/// Throws Error unless `redo_below` is below 1 (NaN included).
void check_redo_below(double redo_below);
/// 1. The verdict on a one pass measured `one_pass`, against the bar
/// redo_below × `original_min` (the lowest quality of the cells valid in the
/// original): fills r.checked, one_pass and bar, and says why not in
/// r.boundary_folds or (a 3D mesh above redo_max_nodes_3d) r.redo_error;
/// true when laplacian should solve the step again.
bool guard_verdict(const DgHarmonicPlan& plan, const GuardMeasure& one_pass, double original_min, double redo_below,
                   DgHarmonicGuardReport& r);
/// 2. laplacian's solve of the step into `redo` (num_points × dim, not
/// aliasing `points`, the original), its plan built on `points` and `cells`
/// the first time (laplacian_plan_of): r.redone and r.increments; false, with
/// r.redo_error, when laplacian cannot solve this mesh (the one pass stays).
/// Throws InvalidResultError as laplacian does. The plan must have a guard.
bool guard_redo(const DgHarmonicPlan& plan, const ElementList& cells, std::span<const double> points,
                const BoundaryMotion& motion, std::span<double> redo, DgHarmonicGuardReport& r);
/// 3. With r.redo the redo's measure: when it is better than the one pass
/// (fewer inverted cells, then a higher minimum), copies it into `out` (the
/// nodes the cells use: laplacian leaves the others) and sets r.kept_redo.
bool guard_keep(const DgHarmonicPlan& plan, std::span<const double> redo, std::span<double> out,
                DgHarmonicGuardReport& r);

/// One line for a report: what the guard measured and did, e.g. "one pass
/// min 0.0250 (bar 0.363, measured in 4.1 ms): solved again by laplacian in 4 increments, min
/// 0.131, kept (102 ms)"; "" when the step was not checked.
std::string guard_summary(const DgHarmonicGuardReport& report);

/// Bytes held by a guard's arrays.
std::size_t guard_bytes(const DgHarmonicGuard& guard);

}  // namespace dgwarp
