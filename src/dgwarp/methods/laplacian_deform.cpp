// deform_laplacian: the stiffened P1 Laplacian, assembled and solved per increment.
#include <Eigen/CholmodSupport>
#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>
#include <algorithm>
#include <cmath>
#include <string>
#include <type_traits>

#include "dgwarp/core/error.hpp"
#include "dgwarp/methods/laplacian.hpp"
#include "dgwarp/methods/method_inputs.hpp"
#include "dgwarp/methods/metis_ordering.hpp"

namespace dgwarp {

namespace {

// The factorisation of an increment's stiffness: in 2D Eigen's simplicial
// LDL^T (METIS ordering); in 3D CHOLMOD's supernodal Cholesky, whose dense
// BLAS blocks suit the fill of 3D elasticity (21.7k-node random scene 5, four
// increments, one thread: 43.6 s simplicial, 12.4 s supernodal with OpenBLAS).
template <int Dim>
using StiffnessSolver =
    std::conditional_t<Dim == 3, Eigen::CholmodSupernodalLLT<Eigen::SparseMatrix<double>, Eigen::Lower>,
                       Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>, Eigen::Lower, MetisOrAmdOrdering>>;

// Whether the factorisation succeeded with a positive definite matrix (a
// singular one: a part of the mesh joined to no boundary node).
template <int Dim>
bool positive_definite(const StiffnessSolver<Dim>& solver) {
    if (solver.info() != Eigen::Success) return false;
    if constexpr (Dim == 3) {
        return true;  // CHOLMOD's Cholesky fails on a matrix that is not positive definite
    } else {
        const Eigen::VectorXd d = solver.vectorD();
        return (d.size() == 0 || d.minCoeff() > 0) && d.allFinite();
    }
}

// The gradients of a simplex's barycentric coordinates (dim + 1 rows of dim)
// and its unsigned measure; false when it is degenerate.
template <int Dim>
bool simplex_gradients(const double* const (&x)[Dim + 1], double (&g)[Dim + 1][Dim], double& measure) {
    double j[Dim][Dim];  // j[r][k] = (x_{k+1} - x_0)[r]
    for (int k = 0; k < Dim; ++k)
        for (int r = 0; r < Dim; ++r) j[r][k] = x[k + 1][r] - x[0][r];
    double inv[Dim][Dim], det;
    if constexpr (Dim == 2) {
        det = j[0][0] * j[1][1] - j[0][1] * j[1][0];
        inv[0][0] = j[1][1];
        inv[0][1] = -j[0][1];
        inv[1][0] = -j[1][0];
        inv[1][1] = j[0][0];
    } else {
        inv[0][0] = j[1][1] * j[2][2] - j[1][2] * j[2][1];
        inv[0][1] = j[0][2] * j[2][1] - j[0][1] * j[2][2];
        inv[0][2] = j[0][1] * j[1][2] - j[0][2] * j[1][1];
        inv[1][0] = j[1][2] * j[2][0] - j[1][0] * j[2][2];
        inv[1][1] = j[0][0] * j[2][2] - j[0][2] * j[2][0];
        inv[1][2] = j[0][2] * j[1][0] - j[0][0] * j[1][2];
        inv[2][0] = j[1][0] * j[2][1] - j[1][1] * j[2][0];
        inv[2][1] = j[0][1] * j[2][0] - j[0][0] * j[2][1];
        inv[2][2] = j[0][0] * j[1][1] - j[0][1] * j[1][0];
        det = j[0][0] * inv[0][0] + j[0][1] * inv[1][0] + j[0][2] * inv[2][0];
    }
    if (!(std::abs(det) > 0) || !std::isfinite(det)) return false;
    // Row k of J^-1 is the gradient of barycentric coordinate k + 1.
    for (int d = 0; d < Dim; ++d) g[0][d] = 0;
    for (int k = 0; k < Dim; ++k)
        for (int d = 0; d < Dim; ++d) {
            g[k + 1][d] = inv[k][d] / det;
            g[0][d] -= g[k + 1][d];
        }
    measure = std::abs(det) / (Dim == 2 ? 2.0 : 6.0);
    return true;
}

// Per cell, its measure: the sum of its simplices' (current coordinates x).
template <int Dim>
std::vector<double> cell_measures(const LaplacianPlan& plan, const std::vector<double>& x) {
    std::vector<double> v(static_cast<std::size_t>(plan.num_cells), 0.0);
    const std::size_t n = plan.simplex_cell.size();
    for (std::size_t s = 0; s < n; ++s) {
        const double* corner[Dim + 1];
        for (int k = 0; k <= Dim; ++k) corner[k] = x.data() + static_cast<std::size_t>(plan.simplices[s * (Dim + 1) + k]) * Dim;
        double g[Dim + 1][Dim], measure = 0;
        if (simplex_gradients<Dim>(corner, g, measure)) v[static_cast<std::size_t>(plan.simplex_cell[s])] += measure;
    }
    return v;
}

// Per simplex of the split mesh, its signed measure (times dim!) at x.
// Then the same of its cells' corner simplices.
template <int Dim>
std::vector<double> signed_measures(const LaplacianPlan& plan, const std::vector<double>& x) {
    const std::size_t split = plan.simplex_cell.size();
    std::vector<double> v(split + plan.corners.size() / (Dim + 1));
    for (std::size_t s = 0; s < v.size(); ++s) {
        const std::int32_t* ids = s < split ? plan.simplices.data() + s * (Dim + 1)
                                            : plan.corners.data() + (s - split) * (Dim + 1);
        double e[Dim][Dim];
        for (int k = 0; k < Dim; ++k)
            for (int d = 0; d < Dim; ++d)
                e[k][d] = x[static_cast<std::size_t>(ids[k + 1]) * Dim + d] - x[static_cast<std::size_t>(ids[0]) * Dim + d];
        if constexpr (Dim == 2) v[s] = e[0][0] * e[1][1] - e[0][1] * e[1][0];
        else
            v[s] = e[0][0] * (e[1][1] * e[2][2] - e[1][2] * e[2][1]) - e[0][1] * (e[1][0] * e[2][2] - e[1][2] * e[2][0]) +
                   e[0][2] * (e[1][0] * e[2][1] - e[1][1] * e[2][0]);
    }
    return v;
}

// Whether a simplex that had a sign lost it (flipped or flat).
bool folds(const std::vector<double>& before, const std::vector<double>& after) {
    for (std::size_t s = 0; s < before.size(); ++s)
        if ((before[s] > 0 && !(after[s] > 0)) || (before[s] < 0 && !(after[s] < 0))) return true;
    return false;
}

// One increment: moves x (split-mesh nodes × Dim) so that the given nodes
// reach `target` (same layout; read at given nodes only).
template <int Dim>
void solve_increment(const LaplacianPlan& plan, std::vector<double>& x, const std::vector<double>& target,
                     StiffnessSolver<Dim>& ldlt, bool& analysed) {
    const std::vector<double> measure = cell_measures<Dim>(plan, x);
    double mean = 0;
    for (double m : measure) mean += m;
    mean /= static_cast<double>(std::max<std::size_t>(measure.size(), 1));
    const double e = plan.options.stiffness_exponent;
    std::vector<double> stiffness(measure.size());
    for (std::size_t c = 0; c < measure.size(); ++c)
        stiffness[c] = e == 0 ? 1.0 : std::pow(mean / std::max(measure[c], 1e-12 * mean), e);

    // Unknowns: the Laplacian solves each component with one matrix (n rows,
    // Dim right-hand sides); elasticity couples them (n Dim rows, dof k Dim + a).
    const bool elastic = plan.options.model == LaplacianModel::elasticity;
    const int block = elastic ? Dim : 1;
    const std::int32_t n = plan.num_unknowns * block;
    const double nu = plan.options.poisson_ratio;
    const double lambda_per_e = nu / ((1 + nu) * (1 - 2 * nu)), mu_per_e = 1 / (2 * (1 + nu));
    std::vector<Eigen::Triplet<double, int>> a;
    a.reserve(plan.simplex_cell.size() * (Dim + 1) * (Dim + 2) / 2 * block * block);
    Eigen::MatrixXd rhs = Eigen::MatrixXd::Zero(n, elastic ? 1 : Dim);
    const std::size_t num_simplices = plan.simplex_cell.size();
    for (std::size_t s = 0; s < num_simplices; ++s) {
        const std::int32_t* ids = plan.simplices.data() + s * (Dim + 1);
        const double* corner[Dim + 1];
        for (int k = 0; k <= Dim; ++k) corner[k] = x.data() + static_cast<std::size_t>(ids[k]) * Dim;
        double g[Dim + 1][Dim], vol = 0;
        const bool ok = simplex_gradients<Dim>(corner, g, vol);
        const double w = ok ? stiffness[static_cast<std::size_t>(plan.simplex_cell[s])] * vol : 0.0;
        for (int i = 0; i <= Dim; ++i) {
            const std::int32_t ui = plan.unknown[static_cast<std::size_t>(ids[i])];
            if (ui < 0) continue;
            for (int j = 0; j <= Dim; ++j) {
                const std::int32_t uj = plan.unknown[static_cast<std::size_t>(ids[j])];
                if (uj < 0 && uj != -1) continue;
                const std::size_t nj = static_cast<std::size_t>(ids[j]) * Dim;
                double dot = 0;
                for (int d = 0; d < Dim; ++d) dot += g[i][d] * g[j][d];
                if (!elastic) {
                    const double kij = w * dot;
                    if (uj >= 0) {
                        if (uj <= ui) a.emplace_back(ui, uj, kij);  // the lower triangle; zeros kept (one pattern)
                    } else {  // a given node: its increment goes to the right-hand side
                        for (int d = 0; d < Dim; ++d) rhs(ui, d) -= kij * (target[nj + d] - x[nj + d]);
                    }
                    continue;
                }
                // K_ij^ab = V E (lambda g_i^a g_j^b + mu g_i^b g_j^a + mu delta_ab g_i.g_j), per unit E.
                for (int p = 0; p < Dim; ++p)
                    for (int q = 0; q < Dim; ++q) {
                        const double kab = w * (lambda_per_e * g[i][p] * g[j][q] + mu_per_e * g[i][q] * g[j][p] +
                                                (p == q ? mu_per_e * dot : 0.0));
                        const int row = ui * Dim + p;
                        if (uj >= 0) {
                            const int col = uj * Dim + q;
                            if (col <= row) a.emplace_back(row, col, kab);
                        } else {
                            rhs(row, 0) -= kab * (target[nj + q] - x[nj + q]);
                        }
                    }
            }
        }
    }
    Eigen::SparseMatrix<double> m(n, n);
    m.setFromTriplets(a.begin(), a.end());
    if (!analysed) {
        if constexpr (Dim == 3) ldlt.cholmod().print = 0;  // its messages are this error's business
        ldlt.analyzePattern(m);
        analysed = true;
    }
    ldlt.factorize(m);
    if (!positive_definite<Dim>(ldlt))
        throw Error("laplacian: the stiffness matrix of the " + std::to_string(n) +
                    " unknowns is singular: a part of the mesh is joined to no boundary node, or its cells are "
                    "degenerate");
    const Eigen::MatrixXd u = ldlt.solve(rhs);
    if (!u.allFinite())
        throw Error("laplacian: the solve of the " + std::to_string(n) + " unknowns gave non-finite displacements");
    const std::size_t total = plan.unknown.size();
    for (std::size_t node = 0; node < total; ++node) {
        const std::int32_t k = plan.unknown[node];
        if (k >= 0)
            for (int d = 0; d < Dim; ++d) x[node * Dim + d] += elastic ? u(k * Dim + d, 0) : u(k, d);
        else if (k == -1)
            for (int d = 0; d < Dim; ++d) x[node * Dim + d] = target[node * Dim + d];
    }
}

// The given nodes' positions at fraction f of the motion: boundary nodes by
// apply_motion of the scaled motion, boundary face centres as their corners' mean.
void given_targets(const LaplacianPlan& plan, std::span<const double> points, const BoundaryMotion& motion, double f,
                   std::vector<double>& target) {
    const int dim = plan.dim;
    for (std::size_t b = 0; b < plan.boundary_nodes.size(); ++b) {
        NodeMotion m = motion[b];
        for (int d = 0; d < 3; ++d) {
            m.translation[d] *= f;
            m.rotation[d] *= f;
        }
        const auto node = static_cast<std::size_t>(plan.boundary_nodes[b]);
        apply_motion(m, points.subspan(node * dim, dim), std::span<double>(target).subspan(node * dim, dim));
    }
    const std::int64_t centres = plan.num_centres();
    for (std::int64_t c = 0; c < centres; ++c) {
        const auto node = static_cast<std::size_t>(plan.num_points + c);
        if (plan.unknown[node] != -1) continue;
        const std::int64_t first = plan.centre_start[c], last = plan.centre_start[c + 1];
        for (int d = 0; d < dim; ++d) {
            double sum = 0;
            for (std::int64_t k = first; k < last; ++k) sum += target[static_cast<std::size_t>(plan.centre_node[k]) * dim + d];
            target[node * dim + d] = sum / static_cast<double>(last - first);
        }
    }
}

template <int Dim>
LaplacianStepReport deform_in(const LaplacianPlan& plan, std::span<const double> points, const BoundaryMotion& motion,
                              std::span<double> out, const ProgressFn& progress, int max_increments) {
    const auto num_points = static_cast<std::size_t>(plan.num_points);
    const std::size_t total = plan.unknown.size();
    // The split mesh's nodes: the points, then the centres (their nodes' mean).
    std::vector<double> x(total * Dim);
    std::copy(points.begin(), points.end(), x.begin());
    for (std::int64_t c = 0; c < plan.num_centres(); ++c) {
        const std::int64_t first = plan.centre_start[c], last = plan.centre_start[c + 1];
        for (int d = 0; d < Dim; ++d) {
            double sum = 0;
            for (std::int64_t k = first; k < last; ++k) sum += points[static_cast<std::size_t>(plan.centre_node[k]) * Dim + d];
            x[(num_points + static_cast<std::size_t>(c)) * Dim + d] = sum / static_cast<double>(last - first);
        }
    }
    const std::vector<double> x0 = x;
    const std::vector<double> before = signed_measures<Dim>(plan, x0);
    std::vector<double> target(x);
    StiffnessSolver<Dim> ldlt;
    bool analysed = false;
    // Twice the increments while a simplex of the split mesh folds, up to max_increments.
    int n = plan.options.increments;
    for (;; n *= 2) {
        x = x0;
        for (int s = 1; s <= n; ++s) {
            given_targets(plan, points, motion, static_cast<double>(s) / n, target);
            if (plan.num_unknowns > 0) solve_increment<Dim>(plan, x, target, ldlt, analysed);
            else
                for (std::size_t node = 0; node < total; ++node)
                    if (plan.unknown[node] == -1)
                        for (int d = 0; d < Dim; ++d) x[node * Dim + d] = target[node * Dim + d];
            if (progress) progress(static_cast<double>(s) / n);
        }
        if (2 * n > max_increments || !folds(before, signed_measures<Dim>(plan, x))) break;
    }
    // Points no cell uses stay; boundary nodes are exactly where apply_motion puts them.
    for (std::size_t node = 0; node < num_points; ++node)
        if (plan.unknown[node] == -2)
            for (int d = 0; d < Dim; ++d) x[node * Dim + d] = points[node * Dim + d];
    std::copy(x.begin(), x.begin() + static_cast<std::ptrdiff_t>(num_points * Dim), out.begin());
    return {n, plan.num_unknowns};
}

}  // namespace

LaplacianStepReport deform_laplacian(const LaplacianPlan& plan, std::span<const double> points,
                                     const BoundaryMotion& motion, std::span<double> out, const ProgressFn& progress) {
    return deform_laplacian_capped(plan, points, motion, out, plan.options.max_increments, progress);
}

LaplacianStepReport deform_laplacian_capped(const LaplacianPlan& plan, std::span<const double> points,
                                            const BoundaryMotion& motion, std::span<double> out, int max_increments,
                                            const ProgressFn& progress) {
    check_step_arrays("laplacian", plan.num_points, plan.dim, plan.boundary_nodes, points, motion, out);
    const int cap = std::min(max_increments, plan.options.max_increments);
    return plan.dim == 2 ? deform_in<2>(plan, points, motion, out, progress, cap)
                         : deform_in<3>(plan, points, motion, out, progress, cap);
}

}  // namespace dgwarp
