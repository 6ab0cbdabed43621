#pragma once
// DG-IDW: Delaunay-graph-based inverse distance weighting (Wang, Qin, Zhao;
// METHODS.md "DG-IDW"). prepare_dg_idw builds a plan once per mesh and
// boundary set; deform_dg_idw moves every node for one step's boundary motion
// in a single pass over the plan, into the caller's array.
//
// Conventions: points are num_points × dim, row-major; node ids are 0-based;
// a "boundary index" b is a position in BoundarySet::nodes (and in a
// BoundaryMotion); volume nodes are the mesh nodes not in the boundary set.
//
// Weights. A volume node x0 lies in a graph simplex with corners v_k at
// distances r_k (original configuration); u_k = 1 / r_k. The paper's
// multipliers are folded into m:
//   one static corner, rest moving  (paper: dim r^-1):  m = dim
//   one moving corner, rest static  (paper: dim a):     m = 1 / dim
//   otherwise                                           m = 1,
// so that with P = sum_moving u_k^2 and Q = sum_static m u_k, and distances
// divided by the length scale L (a (r/L)^-2 = a L^2 u^2, (r/L)^-1 = L u),
// METHODS.md's formula for a component s of (t, w) is
//   s = sum_moving a L^2 u_k^2 s_k / (a L^2 P + L Q) = sigma sum_moving qhat_k s_k,
//   qhat_k = u_k^2 / P,  rho = Q / P,  sigma = 1 / (1 + rho / (a L)).
// The plan stores one number per corner: qhat_k for a moving corner and
// -m u_k / P for a static one (so rho = -sum of the static slots). a and L
// enter only through sigma, which deform computes from the plan's options
// (DgIdwPlan::options; with L = auto, the L prepare computed,
// DgIdwPlan::auto_length_scale): the coefficients do not depend on them, the
// kernel needs no moving/static branch per corner, and the centre
// c = sum_moving qhat_k c_k needs no division. Storing finished weights for
// the two values of a instead would double the per-node plan size.
//
// Continuous weighting (DgIdwWeighting::continuous) multiplies each corner's
// u_k^2 and u_k by the node's barycentric coordinate e_k of that corner
// (clamped at 0) and sets m = 1: P = sum_moving e_k u_k^2, qhat_k =
// e_k u_k^2 / P. The centre takes the same qhat_k, so its weights are the
// moving corners' e_k u_k^2, normalised to sum to 1 over the moving corners
// (a moving corner with e_k = 0, on the far side of the node's face, has no
// say in the centre either); the formulas above are otherwise unchanged.
#include <cstdint>
#include <span>
#include <vector>

#include "dgwarp/core/progress.hpp"
#include "dgwarp/methods/mesh_fingerprint.hpp"
#include "dgwarp/methods/plan_core.hpp"
#include "dgwarp/motion/node_motion.hpp"

namespace dgwarp {

/// How the corners of a volume node's graph simplex are weighted. Chosen at
/// prepare time; the plan keeps it.
enum class DgIdwWeighting : std::uint8_t {
    /// The paper's eq. 2.3-2.4 (METHODS.md), with the dim multipliers of the
    /// one-static and one-moving simplices. The motion jumps across a graph
    /// face where the two simplices' third (fourth) corners differ, which
    /// can fold fine cells that straddle a long graph edge.
    paper = 0,
    /// Our departure (docs/dg-idw.md, "Continuous weights"): every corner's
    /// weight (a r^-2 moving, r^-1 static) is multiplied by the node's
    /// barycentric coordinate of that corner, and there are no multipliers.
    /// On a face the opposite corner's coordinate is 0, so both simplices
    /// give the same motion: continuous across the whole graph.
    continuous = 1,
};

/// "paper" or "continuous".
const char* weighting_name(DgIdwWeighting w);

/// The range of DG-IDW's a (both): beyond it the weights no longer change
/// the result (measured on the NACA0012 turned 45°), and a subnormal a makes
/// 1 / (a L) infinite and the result NaN.
inline constexpr double dg_idw_a_min = 1e-6, dg_idw_a_max = 1e6;

struct DgIdwOptions {
    double a_translation = 7.0;  // a for the translation components (paper: 7)
    double a_rotation = 1.4;     // a for the rotation-vector components (paper: 1.4)
    /// L, the length distances are divided by. 1 reproduces the paper's
    /// formula (which is not scale invariant); 0 = auto: prepare computes L
    /// from the boundary and the a's (DgIdwPlan::auto_length_scale), the plan
    /// keeps 0 here and deform uses that L.
    double length_scale = 1.0;
    /// Corner weights.
    DgIdwWeighting weighting = DgIdwWeighting::paper;
};
// All of them act at prepare time: the plan keeps them (DgIdwPlan::options,
// also in a saved plan) and deform uses the plan's, so a plan always gives
// the result it was made for.

/// What prepare_dg_idw found, and how long its stages took.
struct DgIdwPrepareStats {
    std::int64_t outside_count = 0;  // volume nodes outside the graph's convex hull (nearest hull simplex used)
    std::int64_t snapped_count = 0;  // volume nodes on a graph vertex (they take its motion)
    std::int64_t shared_vertex_count = 0;  // graph vertices standing for several boundary nodes
    std::int64_t graph_vertex_count = 0;   // distinct boundary points
    std::int64_t graph_simplex_count = 0;  // simplices of the Delaunay graph (0 in a loaded plan, which keeps
                                           //   only those holding a volume node: see simplex_motion)
    double graph_seconds = 0;    // Delaunay graph (0 in a loaded plan)
    double locate_seconds = 0;   // point location (0 in a loaded plan)
    double weights_seconds = 0;  // coefficients and the auto length scale (0 in a loaded plan); the mesh
                                 //   fingerprint is made beside the graph build and counted in locate_seconds
};

/// Everything deform_dg_idw needs, as plain arrays (see plan_file.hpp to save it).
/// Its core (plan_core.hpp): the boundary set, shared vertices, and per mesh
/// node the graph simplex of a volume node (those holding a volume node,
/// numbered in order of first use by the nodes) or -1 - b.
struct DgIdwPlan : GraphPlanCore {
    MeshFingerprint mesh;                     // the mesh and boundary set it was built for
    /// L used when options.length_scale == 0: min(D, G / max(a_translation, a_rotation)),
    /// with the a's given to prepare_dg_idw. D is the bounding-box diagonal of
    /// the moving boundary nodes (of all boundary nodes when none moves), the
    /// body's size, as the paper's L = 1 is for its bodies of size 1. G is the
    /// gap between the moving and the static boundary (shortest distance from
    /// a moving to a static graph vertex; D alone when either set is empty).
    /// Why G / a: at equal distance r from a moving and a static vertex the
    /// moving weight a (r/L)^-2 wins when r < a L, so a L is the thickness of
    /// the zone that follows the moving boundary (nearly) rigidly; it must fit
    /// in the gap. Where moving and static boundaries touch (a moving face
    /// bounded by fixed walls) G is one cell, and with L = 1 the first cells
    /// next to the fixed walls would follow the moving face and cross the
    /// walls' nodes (docs/dg-idw-length-scale.md has the measurements).
    double auto_length_scale = 1;
    /// The options prepare was given: the weighting node_coefficients were
    /// made with, and the a's and L that deform uses.
    DgIdwOptions options;
    /// num_simplices × (dim + 1): for each corner of each graph simplex that
    /// holds a volume node (numbered in order of first use by the nodes;
    /// moving corners first in each row, else in CGAL's order), b >= 0
    /// when the corner's graph vertex moves, with the motion of boundary index
    /// b; -1 - b when it is static (b its first boundary index). (The graph
    /// vertex ids themselves are not needed to deform, so they are folded away:
    /// one dependent load less per corner.)
    std::vector<std::int32_t> simplex_motion;
    /// num_volume_nodes × (dim + 1), in ascending node-id order of the volume
    /// nodes: per simplex corner, qhat_k (moving) or -m u_k / P (static), see
    /// above; with continuous weighting u_k^2 and m u_k are multiplied by the
    /// node's barycentric coordinate e_k (clamped at 0), and m = 1 (also the
    /// centre's weights: see the file comment). All zero when no corner
    /// moves; a node on a graph vertex has 1 for that corner if it moves, and
    /// 0 everywhere else.
    std::vector<double> node_coefficients;
    DgIdwPrepareStats stats;
};

/// Builds the plan for `points` (num_points × dim, the original coordinates)
/// and `boundary`: the Delaunay graph of the boundary nodes, the graph simplex
/// of every volume node, and the per-corner coefficients. The options are
/// kept in the plan (DgIdwPlan::options): the weighting chooses the
/// coefficients, a and L are applied by deform (the auto length scale,
/// always stored, uses max(a_translation, a_rotation), see
/// DgIdwPlan::auto_length_scale).
/// Throws MeshError for an inconsistent boundary set (unsorted, duplicate or
/// out-of-range ids, size mismatch) or a degenerate boundary (fewer than
/// dim + 1 distinct points, all collinear / coplanar), Error for bad options.
/// `progress` gets the fraction done (the graph's, then the weights' share).
DgIdwPlan prepare_dg_idw(int dim, std::span<const double> points, const BoundarySet& boundary,
                         const DgIdwOptions& options = {}, const ProgressFn& progress = {});

/// What one deformation step found.
struct DgIdwStepReport {
    /// Shared graph vertices (see DgIdwPlan::shared_offsets) whose boundary
    /// nodes have different motions this step; the vertex used the rule above.
    std::int64_t conflicting_shared_vertices = 0;
};

/// Deforms the mesh for one step. points: the original num_points × dim
/// coordinates the plan was built for; motion: one NodeMotion per boundary
/// index; out: num_points × dim, written completely (it may be `points`
/// itself: each node is read before it is written). Moving boundary nodes
/// move exactly as apply_motion says; static ones are copied (their motion
/// entries are ignored). Each volume node x0 gets the weighted translation t
/// and rotation vector w of its simplex's moving corners and the centre c
/// (their centres averaged with weights r^-2 normalised over the moving
/// corners), and moves to x0 + t + (R(w) - I)(x0 - c). Uses the plan's
/// options.a_translation, a_rotation and length_scale (0 = the plan's auto
/// value). No allocation; results do not depend on the thread count. Throws
/// MeshError when an array size does not match the plan or a motion is not
/// finite (naming the node), Error for bad options in the plan.
/// `progress` gets the fraction of the nodes moved, per block of 16384.
DgIdwStepReport deform_dg_idw(const DgIdwPlan& plan, std::span<const double> points,
                              const BoundaryMotion& motion, std::span<double> out, const ProgressFn& progress = {});

/// Bytes held by the plan's arrays.
std::size_t plan_bytes(const DgIdwPlan& plan);

/// Throws MeshError when `plan` was not built for these points and boundary
/// set ("the plan was made for another mesh (N points vs M)" or the same count
/// with other coordinates / boundary nodes).
void check_plan_fits(const DgIdwPlan& plan, std::span<const double> points, const BoundarySet& boundary);

}  // namespace dgwarp
