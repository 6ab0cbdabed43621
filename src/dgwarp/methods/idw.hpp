#pragma once
// Global inverse distance weighting (Witteveen & Bijl; the paper's eq. 2.1;
// METHODS.md "Baselines"): every volume node takes a weighted average over
// ALL boundary nodes. It is the O(N_b N_v) baseline DG-IDW is compared with,
// so deform_idw is threaded and written for the vectoriser (see idw_deform.cpp).
//
// For a volume node x0 and each component s of (t, w) (translation and
// rotation vector, METHODS.md "Terms"):
//   s(x0) = Σ_D s_i ρ_i^-c_d / (Σ_D ρ_i^-c_d + Σ_S ρ_j^-c_s),  ρ = |x0 - x_i| / L,
// over the moving (D) and static (S) boundary nodes. Static nodes have s = 0,
// so they only add their weight to the denominator. The centre is the
// weight-averaged centre of the moving nodes, c = Σ_D c_i ρ_i^-c_d / Σ_D ρ_i^-c_d
// (as in DG-IDW; exact for one rigid body), and the node moves to
//   x = c + R(w)(x0 - c) + t.
// Boundary nodes move exactly as apply_motion says; static ones stay.
//
// Defaults. The paper gives no values for c_d and c_s ("the proper setting
// varies from case to case"). We take c_d = 3, c_s = 2 with L = the moving
// boundary's diameter: the best of a sweep over c_d, c_s in {2, 2.5, 3, 3.5,
// 4, 5} on the paper's two 2D cases (the rectangle in a box of
// cases/rect_box.hpp and SU2's NACA0012 deformation mesh, each rotated 45°
// and translated by (2, 2)): minimum cell quality 0.35, 0.40, 0.30, 0.50 and
// no inverted cell, where c_s > c_d (e.g. the 3, 5 pair of Luke et al.'s
// two-term weight) inverted cells in 3 of the 4 cases and c_d = c_s = 3 in 1.
// The reason: the far field lies far from the body, and a low static
// exponent spreads its hold over that whole distance, so the motion fades
// gradually across the gap instead of being squeezed against the far field;
// the higher moving exponent keeps the mesh near the body moving with it.
// With c_d != c_s the ratio of the two sums depends on the length unit, so
// distances are divided by L; the default L = 0 means the diagonal of the
// moving nodes' bounding box, which makes the result independent of the unit
// and ties the crossover to the body's size.
//
// Conventions: points num_points × dim, row-major; 0-based node ids; motions
// one NodeMotion per boundary node in BoundarySet order.
#include <cstdint>
#include <span>
#include <vector>

#include "dgwarp/core/progress.hpp"
#include "dgwarp/motion/node_motion.hpp"

namespace dgwarp {

struct IdwOptions {
    double exponent_moving = 3.0;  // c_d, in (0, 16]; integers 1..8 take the fast path
    double exponent_static = 2.0;  // c_s, in (0, 16]; integers 1..8 take the fast path
    /// L, the length distances are divided by; 0 = auto: the bounding-box
    /// diagonal of the moving boundary nodes (of all boundary nodes when none
    /// moves), stored in the plan.
    double length_scale = 0.0;
};

/// Everything deform_idw needs: the boundary nodes and their original
/// coordinates. Nothing is stored per volume node.
struct IdwPlan {
    int dim = 3;
    std::int64_t num_points = 0;
    double auto_length_scale = 1;               // L used when options.length_scale == 0
    std::vector<NodeId> boundary_nodes;         // BoundarySet::nodes (sorted)
    std::vector<std::uint8_t> boundary_moving;  // BoundarySet::moving
    /// num_boundary × dim, row-major, in BoundarySet order: the coordinates
    /// the weights are measured from.
    std::vector<double> boundary_points;

    std::int64_t num_volume_nodes() const {
        return num_points - static_cast<std::int64_t>(boundary_nodes.size());
    }
};

/// Builds the plan for `points` (num_points × dim, original coordinates) and
/// `boundary`. Throws MeshError for a bad boundary set or point array (see
/// check_boundary_set) or a boundary without nodes, Error for bad options.
IdwPlan prepare_idw(int dim, std::span<const double> points, const BoundarySet& boundary,
                    const IdwOptions& options = {});

/// Deforms the mesh for one step. points: the original num_points × dim
/// coordinates; motion: one NodeMotion per boundary node; out: num_points ×
/// dim, written completely (it may be `points` itself). Each volume node sums
/// over all boundary nodes in boundary order, so the result does not depend
/// on the thread count. Throws MeshError when a size does not match the plan,
/// Error for bad options. `progress` gets the fraction of volume nodes moved,
/// per block of them.
void deform_idw(const IdwPlan& plan, std::span<const double> points, const BoundaryMotion& motion,
                std::span<double> out, const IdwOptions& options = {}, const ProgressFn& progress = {});

/// Bytes held by the plan's arrays.
std::size_t plan_bytes(const IdwPlan& plan);

/// Throws Error when an exponent is not in (0, 16] or L is not finite and >= 0.
void check_idw_options(const IdwOptions& options);

}  // namespace dgwarp
