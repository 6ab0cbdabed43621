#pragma once
// DG-harmonic: the robust method (docs/dg-harmonic.md). Two levels:
//
//  * Coarse level, built once: the boundary nodes plus a few volume nodes
//    chosen with a spacing that grows away from the walls (coarse_points.hpp),
//    and the Delaunay triangulation of all of them (the "coarse graph"). On
//    it, two P1 finite-element Laplacians with a conductivity per simplex,
//    factorised once: one for the translation (conductivity size^-3 in 2D,
//    size^-2.5 in 3D: stiff where cells are small, so the strain goes where
//    cells are large), one for the rotation (2D: conductivity 1 times a
//    rigid-zone factor near the moving body, since the rotation angle's drop
//    times the lever arm is the shear; 3D: the translation's, so one factor
//    serves both).
//  * Every step, the motion (METHODS.md's t, w and centre c) is carried from
//    the boundary vertices to the coarse interior vertices by the two
//    harmonic solves (Dirichlet data on the boundary; a forward and a
//    backward substitution per system for all its components at once), then
//    to every other volume node by its barycentric coordinates in the coarse
//    graph, and the node moves to c + R(w)(x0 - c) + t like DG-IDW's nodes.
//
// Why it does not fold cells where the one-pass methods do: the Laplacians'
// off-diagonal weights are kept non-negative, so every interpolated component
// is a convex combination of the boundary values (discrete maximum principle:
// no overshoot, no motion larger than the boundary's); the coarse points put
// interior vertices between a moving and a fixed wall, so the motion decays
// across the gap instead of inside one sliver; barycentric interpolation is
// continuous across the coarse graph's faces (DG-IDW's paper weights jump
// there). The centre is interpolated as (|w| c) / |w|, so a translating
// body's arbitrary centre does not pull on a rotating one's.
//
// Each step is computed from the original points (no drift: a motion that
// returns to zero returns every node to its original position, to round-off).
// Results do not depend on the thread count.
#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <vector>

#include "dgwarp/core/progress.hpp"
#include "dgwarp/methods/mesh_fingerprint.hpp"
#include "dgwarp/methods/plan_core.hpp"
#include "dgwarp/motion/node_motion.hpp"

namespace dgwarp {

struct DgHarmonicOptions {
    /// Coarse spacing next to a wall, in multiples of the local spacing of
    /// the boundary nodes (distance from the nearest boundary node to its
    /// nearest neighbour on the boundary). Prepare time. The defaults were
    /// chosen by measurement (docs/dg-harmonic.md).
    double wall_spacing = 6.0;
    /// Coarse spacing away from the walls, as a fraction of the distance to
    /// the nearest boundary node: spacing = max(wall_spacing h_b, growth d).
    /// Prepare time.
    double growth = 1.0;
    /// Conductivity of a coarse simplex in the two Laplacians:
    /// size^-translation_exponent for the translation, size^-rotation_exponent
    /// for the rotation (times the rigid-zone factor); size is the simplex's
    /// mean edge length. Prepare time, 0 to 4. Unset: the dimension's
    /// default (translation: 3 in 2D, 2.5 in 3D; rotation: 0 in 2D, 2.5 in
    /// 3D; docs/dg-harmonic.md has the measurements); a plan's are set.
    std::optional<double> translation_exponent = std::nullopt;
    std::optional<double> rotation_exponent = std::nullopt;
    /// Rigid zone of the rotation: a simplex closer to the moving boundary
    /// than rho = min(rigid_zone D, rigid_gap d_s) is stiffened by
    /// 1 + (rho / d_m)^2 (D: the moving boundary's bounding-box diagonal; d_m,
    /// d_s: the mean distances of its corners to the nearest moving and
    /// static boundary nodes, d_m at least half its size). Prepare time.
    /// Unset: the dimension's default (0.25 in 2D, 0 in 3D); a plan's is set.
    /// rigid_gap: negative takes 0.5.
    std::optional<double> rigid_zone = std::nullopt;
    double rigid_gap = 0.5;
    /// The guard (dg_harmonic_guard.hpp), at step time, when the plan was
    /// prepared with the mesh's cells: a step that inverts a cell or whose
    /// minimum quality falls below redo_below × the original mesh's is solved
    /// again by the laplacian reference and the better result kept. 0: only
    /// a step that inverts a cell; negative: never measured (the one pass).
    /// Not part of the plan's arrays (a plan file does not keep it).
    /// The default was chosen on the 3D random scenes 1-25 and checked on
    /// others (docs/dg-harmonic.md, "The guard").
    double redo_below = 0.8;
    /// When the one pass folds, the guard's laplacian doubles its increments
    /// while a cell folds up to this many (at most laplacian's own
    /// max_increments; a step that folds even so has cost 4 + 8 + ... + 64
    /// solves). A valid one pass below the bar gets one solve of laplacian's
    /// increments, not doubled. Prepare time.
    int redo_max_increments = 64;
    /// The guard solves a 3D step again only on meshes of at most this many
    /// nodes: the laplacian factorises the 3D elasticity stiffness at every
    /// increment, and its cost grows about as the square of the nodes (12 s
    /// for 4 increments at 21.7k nodes, one thread; hours at 865k). Above it
    /// the one pass stays and the report says why (redo_error). 2D: no limit.
    std::int64_t redo_max_nodes_3d = 100000;
};

/// What prepare_dg_harmonic found, and how long its stages took.
struct DgHarmonicPrepareStats {
    std::int64_t coarse_interior = 0;      // volume nodes on the coarse level (unknowns of the solve)
    std::int64_t graph_vertices = 0;       // vertices of the coarse graph (distinct boundary points + interior)
    std::int64_t outside_count = 0;        // volume nodes outside the coarse graph's hull
    std::int64_t shared_vertex_count = 0;  // coarse graph vertices standing for several boundary nodes
    std::int64_t factor_nonzeros = 0;      // nonzeros of the Cholesky factor L
    std::int64_t floored_weights = 0;      // edge weights raised to the floor after a zero pivot (coarse_laplacian.hpp); 0 normally
    double select_seconds = 0;             // wall distances and coarse point selection
    double graph_seconds = 0;              // Delaunay triangulation of the coarse points
    double locate_seconds = 0;             // location of the volume nodes
    double factor_seconds = 0;             // Laplacian assembly, ordering and factorisation
    double guard_seconds = 0;              // the guard: the cells' orientations and original quality (prepare with cells)
};

/// The two factorised Laplacians of the coarse graph (translation and
/// rotation). They have the same sparsity, so they share the ordering and the
/// factor's structure. Unknown u (one per interior vertex, in the order vertex
/// num_boundary_vertices + i) satisfies A u = B g, with g the boundary
/// vertices' values. A = P^T L D L^T P: perm[i] is the position of unknown i
/// in the factor's order; L is unit lower triangular in compressed columns
/// (l_start, l_row, and per system l_value; the diagonal is not stored), d
/// its diagonal. B in compressed rows per unknown: coupling_start,
/// coupling_vertex (a boundary vertex), and per system coupling_weight.
struct HarmonicFactors {
    std::vector<std::int32_t> perm;
    std::vector<std::int64_t> l_start{0};
    std::vector<std::int32_t> l_row;
    std::vector<std::int64_t> coupling_start{0};
    std::vector<std::int32_t> coupling_vertex;
    struct System {
        std::vector<double> l_value;
        std::vector<double> d;
        std::vector<double> coupling_weight;
    };
    System translation, rotation;
    /// The two Laplacians are the same (same conductivity, no rigid zone):
    /// `rotation` is empty and one solve carries every component.
    bool shared = false;

    std::int64_t num_unknowns() const { return static_cast<std::int64_t>(perm.size()); }
};

/// Everything deform_dg_harmonic needs, as plain arrays.
struct DgHarmonicGuard;

/// Its core (plan_core.hpp): the boundary set, the coarse graph's shared
/// vertices, and per mesh node the coarse simplex of a volume node or -1 - b.
struct DgHarmonicPlan : GraphPlanCore {
    MeshFingerprint mesh;
    DgHarmonicOptions options;                  // as prepare used them (resolved_options; they shape every array below)
    /// Per coarse graph vertex: b >= 0 when it is a boundary point that moves
    /// with the motion of boundary index b; -1 - b when it is a static
    /// boundary point; for interior (unknown) vertices, ignored (see
    /// num_boundary_vertices: boundary vertices come first).
    std::vector<std::int32_t> vertex_motion;
    std::int32_t num_boundary_vertices = 0;
    /// num_simplices × (dim + 1) coarse graph vertex ids.
    std::vector<std::int32_t> simplices;
    /// num_volume_nodes × (dim + 1), ascending node-id order of the volume
    /// nodes: barycentric coordinates in the node's coarse simplex, clamped
    /// at 0 and scaled to sum 1 (a node outside the hull takes the nearest
    /// point of its simplex's motion, no extrapolation).
    std::vector<double> node_barycentric;
    /// The two harmonic systems: translation components, and rotation
    /// components (w, |w|, |w| c).
    HarmonicFactors solve;
    DgHarmonicPrepareStats stats;
    /// The guard: the mesh's cells and the laplacian plan that solves a step
    /// again (dg_harmonic_guard.hpp); null when prepared without cells (a
    /// point cloud, a distributed part, a plan file before
    /// attach_dg_harmonic_guard). Shared, read-only: copies of a plan share it.
    std::shared_ptr<const DgHarmonicGuard> guard;

    std::int64_t num_vertices() const { return static_cast<std::int64_t>(vertex_motion.size()); }
    std::int64_t num_unknowns() const { return solve.num_unknowns(); }
};

/// Builds the plan for `points` (num_points × dim, the original coordinates)
/// and `boundary`. Throws MeshError for an inconsistent boundary set or a
/// degenerate boundary (as DG-IDW), Error for bad options.
/// `progress` gets the fraction done.
DgHarmonicPlan prepare_dg_harmonic(int dim, std::span<const double> points, const BoundarySet& boundary,
                                   const DgHarmonicOptions& options = {}, const ProgressFn& progress = {});

struct DgHarmonicStepReport {
    /// Shared graph vertices whose boundary nodes have different motions this step.
    std::int64_t conflicting_shared_vertices = 0;
};

/// One step: writes every node's new position to `out` (num_points × dim; may
/// be `points`). Boundary nodes move exactly as apply_motion says (static
/// ones are copied). Throws MeshError when an array size does not match the
/// plan or a motion is not finite. `progress` gets the fraction of the
/// nodes moved by the pass after the coarse solve, per block of 16384.
DgHarmonicStepReport deform_dg_harmonic(const DgHarmonicPlan& plan, std::span<const double> points,
                                        const BoundaryMotion& motion, std::span<double> out,
                                        const ProgressFn& progress = {});

/// Bytes held by the plan's arrays.
std::size_t plan_bytes(const DgHarmonicPlan& plan);

/// Throws MeshError when `plan` was not built for these points and boundary
/// set (as check_plan_fits for DG-IDW plans).
void check_plan_fits(const DgHarmonicPlan& plan, std::span<const double> points, const BoundarySet& boundary);

/// Throws Error when an option is out of range (naming it).
void check_dg_harmonic_options(const DgHarmonicOptions& options);

/// `options` with the dimension's defaults in place of negative values.
DgHarmonicOptions resolved_options(const DgHarmonicOptions& options, int dim);

}  // namespace dgwarp
