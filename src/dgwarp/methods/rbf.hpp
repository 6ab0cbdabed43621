#pragma once
// Radial basis function mesh deformation (de Boer, van der Schoot & Bijl;
// METHODS.md "Baselines"), with the greedy data reduction of Rendall & Allen.
//
// What is interpolated: the displacement of the boundary nodes, d_b =
// apply_motion(x_b) - x_b (zero for static nodes), one scalar field per
// coordinate, as de Boer et al. do. A volume node moves to x0 + s(x0) with
//   s(x) = Σ_j α_j φ(|x - x_j| / R) + β_0 + Σ_k β_k (x_k - x̄_k) / D,
// φ the Wendland C2 function (1 - ξ)^4 (4ξ + 1) for ξ < 1, else 0, and a
// linear polynomial written in shifted, scaled coordinates (x̄ the centre of
// the boundary's bounding box, D its diagonal) to keep its part of the system
// well scaled. The coefficients solve
//   [M  P] [α]   [d_b]
//   [Pᵀ 0] [β] = [ 0 ],   M_ij = φ(|x_i - x_j| / R),  P_i = [1, (x_i - x̄) / D].
// The rotation-aware (t, w) form of IDW is not needed: a rigid motion's
// displacement (R(w) - I)(x - c) + t is linear in x, so the polynomial
// reproduces it exactly. Boundary nodes themselves move exactly as
// apply_motion says, whatever the interpolant does there.
//
// Solving. M is symmetric positive definite (Wendland's C2 function is
// positive definite in up to 3 dimensions), so the polynomial part is
// eliminated rather than factorising the indefinite saddle-point matrix:
//   G = M⁻¹ P,  H = Pᵀ G,  β = H⁻¹ Pᵀ M⁻¹ d,  α = M⁻¹ d - G β,
// with one Cholesky factorisation of M at prepare time: dense (Eigen LLT, in
// place) when the support is global, sparse (Eigen SimplicialLDLT, AMD
// ordering; neighbours from a nanoflann k-d tree) when it is compact. Each
// motion then costs two triangular solves per coordinate.
//
// Greedy reduction (Rendall & Allen), per motion: start from the node of
// largest |d| (plus dim nodes spanning the boundary, which the linear
// polynomial needs to be determined), then repeatedly add the boundary node
// where the interpolant is worst until the largest error |s(x_b) - d_b| is at
// most the tolerance. Each step extends a dense Cholesky factor of the
// centres' matrix by one row. The volume is then evaluated with the kept
// centres only.
//
// Conventions: points num_points × dim, row-major; 0-based node ids; a
// "boundary index" is a position in BoundarySet::nodes.
#include <array>
#include <cstdint>
#include <memory>
#include <span>
#include <vector>

#include "dgwarp/core/progress.hpp"
#include "dgwarp/motion/node_motion.hpp"

namespace dgwarp {

/// How the full system is factorised (greedy reduction always uses its own
/// small dense factor).
enum class RbfSolver {
    automatic,  // dense when the support is global (R >= the boundary's diagonal), sparse otherwise
    dense,      // Eigen LLT of the N_b × N_b matrix
    sparse,     // Eigen SimplicialLDLT of the sparse matrix (any R)
};

/// Options act at prepare time; the plan keeps them.
struct RbfOptions {
    /// R; 0 = global: the diagonal of the boundary nodes' bounding box, so
    /// every pair of boundary nodes (and every volume node inside the box)
    /// is within the support.
    double support_radius = 0;
    /// Greedy reduction: the largest allowed boundary error |s(x_b) - d_b|,
    /// in mesh length units; 0 = no reduction (all boundary nodes are centres).
    double greedy_tolerance = 0;
    /// Largest dense system prepare (or the greedy reduction) may allocate;
    /// beyond it they throw. 0 = auto: half the machine's physical memory.
    std::size_t max_dense_bytes = 0;
    RbfSolver solver = RbfSolver::automatic;
};

struct RbfFactorization;  // the factorised full system (rbf_factorization.hpp)
struct RbfCentreIndex;    // a k-d tree over centres (rbf_centre_index.hpp)

/// What prepare_rbf built, and how long it took.
struct RbfPrepareStats {
    std::int64_t matrix_nonzeros = 0;  // stored entries of M (lower triangle); 0 with greedy reduction
    std::size_t factor_bytes = 0;      // bytes of the factorisation and G
    double matrix_seconds = 0;         // building M (and the k-d tree)
    double factor_seconds = 0;         // factorising M, G and H
};

/// Everything deform_rbf needs. Copies share the (immutable) factorisation.
struct RbfPlan {
    int dim = 3;
    std::int64_t num_points = 0;
    std::vector<NodeId> boundary_nodes;         // BoundarySet::nodes (sorted)
    std::vector<std::uint8_t> boundary_moving;  // BoundarySet::moving
    /// The centres: the distinct positions of the boundary nodes, num_centres
    /// × dim, row-major, in the order of their first boundary index. Boundary
    /// nodes at the same coordinates (zero-length boundary edges) are one
    /// centre: two equal centres would make M singular.
    std::vector<double> centre_points;
    /// Per centre: the boundary index whose motion it interpolates (the first
    /// moving node at that position, else the first node), as DG-IDW's graph vertices.
    std::vector<std::int32_t> centre_source;
    /// Centres standing for several boundary nodes: group g holds boundary
    /// indices shared_members[shared_offsets[g] .. shared_offsets[g+1]), ascending.
    std::vector<std::int32_t> shared_offsets{0};
    std::vector<std::int32_t> shared_members;
    double radius = 0;            // R used
    double diagonal = 0;          // D: the boundary's bounding-box diagonal
    std::array<double, 3> shift{};  // x̄: the centre of the boundary's bounding box
    bool compact = false;         // R < D: k-d tree neighbour searches
    bool dense = false;           // the full system is factorised densely (else sparse, or not at all)
    double greedy_tolerance = 0;  // 0: the full system, factorised here
    std::size_t max_dense_bytes = 0;  // resolved (never 0)
    std::shared_ptr<const RbfFactorization> factorization;  // null with greedy reduction
    std::shared_ptr<const RbfCentreIndex> index;            // over centre_points; null unless compact
    RbfPrepareStats stats;

    std::size_t num_centres() const { return centre_source.size(); }
    std::int64_t num_volume_nodes() const {
        return num_points - static_cast<std::int64_t>(boundary_nodes.size());
    }
};

/// Builds the plan for `points` (num_points × dim, original coordinates) and
/// `boundary`. Without greedy reduction it builds and factorises M.
/// Throws MeshError for a bad point array or boundary set, fewer than dim + 1
/// distinct boundary positions, or boundary nodes that are all collinear (2D) / coplanar
/// (3D) so the linear polynomial is undetermined; Error for bad options, for
/// a dense system larger than max_dense_bytes (the message gives the bytes it
/// would need), and for a matrix that is numerically not positive definite
/// (support radius far too large for the node spacing).
/// `progress` gets the fraction done: per column while building M, then at
/// the end of the factorisation and of G and H (fixed shares of the time).
RbfPlan prepare_rbf(int dim, std::span<const double> points, const BoundarySet& boundary,
                    const RbfOptions& options = {}, const ProgressFn& progress = {});

/// What one step did.
struct RbfStepReport {
    std::int64_t centres = 0;    // centres used (all distinct boundary positions without reduction)
    double boundary_error = 0;   // max over the centres of |s(x_c) - d_c| (mesh units)
    std::int64_t conflicting_shared_centres = 0;  // centres whose boundary nodes were given different motions
    double solve_seconds = 0;    // coefficients (including the greedy loop)
    double evaluate_seconds = 0; // volume nodes
};

/// The interpolant of one motion.
struct RbfCoefficients {
    int dim = 3;
    std::vector<std::int32_t> centres;  // index of each centre in the plan's centre_points
    std::vector<double> centre_points;  // centres.size() × dim, row-major
    std::vector<double> alpha;          // centres.size() × dim, row-major
    /// (dim + 1) × dim, row-major: the constant row, then one row per
    /// coordinate of (x - shift) / diagonal.
    std::vector<double> beta;
    std::shared_ptr<const RbfCentreIndex> index;  // over centre_points; null unless the plan is compact
    RbfStepReport report;                         // centres, boundary_error, solve_seconds
};

/// The displacements of the centres d_c = apply_motion(x_c) - x_c of one
/// motion, with the motion of centre_source[c] (zero for a static one):
/// num_centres × dim, row-major.
std::vector<double> rbf_boundary_displacements(const RbfPlan& plan, const BoundaryMotion& motion);

/// Solves for the interpolant of `motion` (one NodeMotion per boundary node):
/// with the plan's factorisation, or by greedy reduction. Fills
/// report.centres and report.boundary_error. Throws MeshError on a size
/// mismatch, Error when the greedy reduction would exceed max_dense_bytes.
RbfCoefficients solve_rbf(const RbfPlan& plan, const BoundaryMotion& motion);

/// The interpolated displacement s(x) at `x` (n × dim, row-major) into
/// `displacement` (n × dim). Threaded; results do not depend on the thread count.
void evaluate_rbf(const RbfPlan& plan, const RbfCoefficients& coefficients, std::span<const double> x,
                  std::span<double> displacement);

/// Deforms the mesh for one step: solve_rbf, then every volume node x0 moves
/// to x0 + s(x0) (threaded) and every boundary node as apply_motion says
/// (static ones stay). points: the original num_points × dim coordinates;
/// out: num_points × dim, written completely (it may be `points`). Throws as
/// solve_rbf does, and MeshError when an array size does not match the plan.
/// `progress` gets the fraction done: the solve's share at its end, then per
/// block of volume nodes evaluated.
RbfStepReport deform_rbf(const RbfPlan& plan, std::span<const double> points, const BoundaryMotion& motion,
                         std::span<double> out, const ProgressFn& progress = {});

/// Bytes held by the plan (its arrays, factorisation and k-d tree).
std::size_t plan_bytes(const RbfPlan& plan);

/// Wendland's C2 function (1 - ξ)^4 (4ξ + 1) for 0 <= ξ < 1, else 0.
inline double wendland_c2(double xi) {
    if (xi >= 1) return 0;
    const double u = 1 - xi;
    return u * u * u * u * (4 * xi + 1);
}

}  // namespace dgwarp
