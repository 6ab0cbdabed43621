#pragma once
// DGM: Delaunay graph mapping (Liu, Qin, Xia 2006; METHODS.md "DGM"), one of
// the paper's comparison methods. prepare_dgm builds the same Delaunay graph of
// the boundary nodes and the same point location as DG-IDW, and stores the
// barycentric (area / volume ratio) coordinates e_k of every volume node in its
// graph simplex. deform_dgm moves the graph vertices to their new positions
// X_k' and maps each volume node to x' = sum_k e_k X_k'.
//
// The mapping is only valid while the moved graph is: every graph simplex must
// keep a positive signed area / volume (judged with CGAL's exact orientation
// predicate; simplices flat to round-off before and after the move are
// exempt, see graph/simplex_orientation.hpp). A large rotation folds the graph over itself (the paper's
// Fig. 10, a 90° rotation of the rectangle in a box); DgmOptions says what
// happens then.
//
// Conventions: points are num_points × dim, row-major; node ids are 0-based;
// a "boundary index" b is a position in BoundarySet::nodes (and in a
// BoundaryMotion); volume nodes are the mesh nodes not in the boundary set.
// Boundary nodes with identical coordinates are one graph vertex, which moves
// by DG-IDW's rule (graph_vertex_motion.hpp).
#include <cstdint>
#include <span>
#include <vector>

#include "dgwarp/core/progress.hpp"
#include "dgwarp/methods/plan_core.hpp"
#include "dgwarp/motion/node_motion.hpp"

namespace dgwarp {

struct DgmOptions {
    /// What deform_dgm does when the moved graph has flat or inverted simplices.
    enum class OnInvalidGraph {
        /// Throw InvalidResultError; its count() is the number of invalid
        /// simplices (the paper's "-" entries). `out` is left untouched.
        fail,
        /// Split the motion into k equal increments and map increment by
        /// increment, rebuilding the Delaunay graph of the boundary at its
        /// current positions and relocating the current volume node positions
        /// between increments; k = 2, 4, 8, ... up to max_substeps, until every
        /// increment's moved graph is valid (else InvalidResultError as for fail).
        /// Increment j of k moves each boundary node by its NodeMotion scaled by
        /// f = j/k: translation f·t, rotation vector f·w, same centre c. For a
        /// rigid motion (one (t, w, c) per body) every intermediate boundary is
        /// the same rigid motion by a fraction of the angle and translation, so
        /// the body follows the rigid path c + R(f w)(x - c) + f t. For general
        /// per-node motions each node follows its own such path: a displacement
        /// file (w = 0) is moved along straight lines, x + f d, and the
        /// intermediate boundaries are interpolations that need not be shapes
        /// the user prescribed (they are only used to steer the volume nodes).
        /// Sub-steps keep the graph valid, so no volume node crosses a moved
        /// boundary; they do not stop DGM from shearing near-wall cells (cells
        /// at a rotating body's corners can still invert).
        substep,
    };
    OnInvalidGraph on_invalid = OnInvalidGraph::fail;
    /// Largest number of increments `substep` may use (>= 1); the last try uses
    /// exactly this many when doubling would overshoot it.
    int max_substeps = 64;
};

/// What prepare_dgm found, and how long its stages took.
struct DgmPrepareStats {
    std::int64_t outside_count = 0;        // volume nodes outside the graph's hull (extrapolated)
    std::int64_t shared_vertex_count = 0;  // graph vertices standing for several boundary nodes
    double graph_seconds = 0;              // Delaunay graph
    double locate_seconds = 0;             // point location
    double barycentric_seconds = 0;        // barycentric coordinates
};

/// Everything deform_dgm needs, as plain arrays.
/// Its core (plan_core.hpp): the boundary set, shared vertices, and per mesh
/// node the graph simplex of a volume node or -1 - b.
struct DgmPlan : GraphPlanCore {
    /// num_simplices × (dim + 1) graph vertex ids, positively oriented in the
    /// original configuration.
    std::vector<std::int32_t> simplices;
    /// Per graph vertex: b >= 0 when it moves, with the motion of boundary index b;
    /// -1 - b when it is static (b its first boundary index). Its original
    /// position is that of boundary node boundary_nodes[b].
    std::vector<std::int32_t> vertex_motion;
    /// num_volume_nodes × (dim + 1): barycentric coordinates e_k of each volume
    /// node in its simplex (corner order of `simplices`), in ascending node-id
    /// order of the volume nodes; they sum to 1. Negative for a node outside
    /// the graph's hull, which is extrapolated from the hull simplex facing it.
    std::vector<double> node_barycentric;
    DgmPrepareStats stats;
};

/// Builds the plan for `points` (num_points × dim, the original coordinates)
/// and `boundary`: the Delaunay graph of the boundary nodes, the graph simplex
/// of every volume node (the hull simplex facing it when it lies outside the
/// hull) and its barycentric coordinates there.
/// Throws MeshError for an inconsistent boundary set (unsorted, duplicate or
/// out-of-range ids, size mismatch) or a degenerate boundary (fewer than
/// dim + 1 distinct points, all collinear / coplanar), Error for bad options.
/// `progress` gets the fraction done (the graph's, then the coordinates' share).
DgmPlan prepare_dgm(int dim, std::span<const double> points, const BoundarySet& boundary,
                    const DgmOptions& options = {}, const ProgressFn& progress = {});

/// What one deformation step found.
struct DgmStepReport {
    /// Graph simplices that are flat or inverted when the graph is moved by the
    /// whole motion in one step (0 when the one-step mapping is valid), also
    /// when sub-steps then succeeded.
    std::int64_t invalid_simplices = 0;
    /// Increments used: 1 for the one-step mapping, more after sub-stepping.
    int substeps = 1;
    /// Shared graph vertices whose boundary nodes have different motions this
    /// step (the vertex used the rule of graph_vertex_motion.hpp).
    std::int64_t conflicting_shared_vertices = 0;
};

/// Deforms the mesh for one step. points: the original num_points × dim
/// coordinates the plan was built for; motion: one NodeMotion per boundary
/// index; out: num_points × dim, written completely on success and not at all
/// on failure (it may be `points` itself). Boundary nodes move exactly as
/// apply_motion says (static ones are copied). When the moved graph is valid, a
/// volume node x0 goes to x0 + sum_k e_k (X_k' - X_k), which is sum_k e_k X_k'
/// (the e_k reproduce x0) but keeps zero motion exactly the identity. So any
/// affine motion of the boundary (rigid ones included) is reproduced for the
/// nodes inside the hull. When it is not valid, options.on_invalid decides
/// (see DgmOptions). Results do not depend on the thread count.
/// Throws MeshError when an array size does not match the plan, Error for bad
/// options, InvalidResultError when the graph cannot be moved validly:
/// count() is the number of invalid simplices of the one-step graph (`fail`)
/// or of the first invalid increment of the last try (`substep`).
DgmStepReport deform_dgm(const DgmPlan& plan, std::span<const double> points, const BoundaryMotion& motion,
                         std::span<double> out, const DgmOptions& options = {});

/// Bytes held by the plan's arrays.
std::size_t plan_bytes(const DgmPlan& plan);

}  // namespace dgwarp
