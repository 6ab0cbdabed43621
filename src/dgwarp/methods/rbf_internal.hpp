#pragma once
// Internal to RBF: the pieces rbf.cpp, rbf_solve.cpp, rbf_greedy.cpp and
// rbf_evaluate.cpp share. Eigen stays inside rbf_solve.cpp and rbf_greedy.cpp.
#include <cmath>
#include <cstddef>
#include <memory>
#include <span>
#include <string>

#include "dgwarp/methods/rbf.hpp"

namespace dgwarp {

/// φ(|x - x_j| / R) from the squared distance r2 and 1 / R, without a branch
/// (so loops over it vectorise): the same bits as wendland_c2(sqrt(r2) * inv_radius).
inline double wendland_c2_r2(double r2, double inv_radius) {
    const double xi = std::sqrt(r2) * inv_radius;
    double u = 1 - xi;
    u = 0.5 * (u + std::abs(u));  // max(u, 0), exactly
    const double u2 = u * u;
    return u2 * u2 * (4 * xi + 1);
}

/// Squared distance between two points of `dim` coordinates.
inline double distance2(int dim, const double* a, const double* b) {
    double s = 0;
    for (int d = 0; d < dim; ++d) s += (a[d] - b[d]) * (a[d] - b[d]);
    return s;
}

/// The polynomial basis at x: row[0] = 1, row[1 + k] = (x_k - shift_k) / diagonal.
inline void polynomial_row(const RbfPlan& plan, const double* x, double* row) {
    row[0] = 1;
    for (int k = 0; k < plan.dim; ++k) row[1 + k] = (x[k] - plan.shift[k]) / plan.diagonal;
}

/// Throws Error when `needed` bytes exceed plan.max_dense_bytes; `what` says
/// what would be allocated.
void check_dense_bytes(std::size_t needed, std::size_t max_dense_bytes, const std::string& what);

/// Builds and factorises M (dense or sparse, as plan.dense says), G and H
/// (rbf.hpp); fills stats. Reports to `progress` (prepare_rbf's shares).
std::shared_ptr<const RbfFactorization> factorize_rbf(const RbfPlan& plan, RbfPrepareStats& stats,
                                                      const ProgressFn& progress);

/// Bytes held by a factorisation.
std::size_t factorization_bytes(const RbfFactorization& f);

/// The full interpolant of displacements d (num_boundary × dim) with the
/// plan's factorisation: fills centres, centre_points, alpha, beta, index.
void solve_full(const RbfPlan& plan, std::span<const double> d, RbfCoefficients& c);

/// Greedy reduction (rbf.hpp) for displacements d: fills everything
/// solve_full does, plus report.centres and report.boundary_error.
void solve_greedy(const RbfPlan& plan, std::span<const double> d, RbfCoefficients& c);

/// Moves every volume node x0 of `points` to x0 + s(x0) in `out` (threaded),
/// adding the nodes moved to `moved` per block.
void move_volume_nodes(const RbfPlan& plan, const RbfCoefficients& c, std::span<const double> points,
                       std::span<double> out, ProgressCounter& moved);

}  // namespace dgwarp
