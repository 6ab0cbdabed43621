// The full RBF system: M factorised once (dense LLT in place, or sparse
// SimplicialLDLT), the polynomial part eliminated through G = M⁻¹P and
// H = PᵀG (see rbf.hpp), and the per-motion solve.
#include <Eigen/Cholesky>
#include <Eigen/Dense>
#include <Eigen/SparseCholesky>
#include <algorithm>
#include <optional>
#include <string>
#include <vector>

#include "dgwarp/core/error.hpp"
#include "dgwarp/core/parallel_for.hpp"
#include "dgwarp/core/stopwatch.hpp"
#include "dgwarp/methods/rbf_centre_index.hpp"
#include "dgwarp/methods/rbf_internal.hpp"

namespace dgwarp {

using RowMajor = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;

struct RbfFactorization {
    bool dense = true;
    Eigen::MatrixXd m;  // dense: M's lower triangle, overwritten by its Cholesky factor
    std::optional<Eigen::LLT<Eigen::Ref<Eigen::MatrixXd>>> llt;  // in place in m
    Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> ldlt;     // sparse
    std::size_t sparse_factor_bytes = 0;
    Eigen::MatrixXd p;               // P, num_boundary × (dim + 1)
    Eigen::MatrixXd g;               // M⁻¹ P
    Eigen::LLT<Eigen::MatrixXd> h;   // Pᵀ M⁻¹ P

    RbfFactorization() = default;
    RbfFactorization(const RbfFactorization&) = delete;  // llt refers to m
    RbfFactorization& operator=(const RbfFactorization&) = delete;

    Eigen::MatrixXd solve(const Eigen::MatrixXd& rhs) const {
        if (dense) return llt->solve(rhs);
        return ldlt.solve(rhs);
    }
};

namespace {

std::string not_positive_definite(const RbfPlan& plan) {
    return "RBF: the " + std::to_string(plan.num_centres()) + " x " + std::to_string(plan.num_centres()) +
           " interpolation matrix is numerically not positive definite (support radius " +
           std::to_string(plan.radius) +
           " is too large for the spacing of the boundary nodes); use a smaller support radius (rbf_radius in "
           "Python, --rbf-radius in the CLI) or greedy reduction (rbf_greedy, --rbf-greedy)";
}

// Shares of prepare_rbf's progress: building M ends at matrix_share, the
// Cholesky factorisation at factor_share, G and H at 1. Eigen's factorisations
// report nothing while they run; these shares are rough averages of their times.
constexpr double dense_matrix_share = 0.1, sparse_matrix_share = 0.3, factor_share = 0.9;

void factorize_dense(const RbfPlan& plan, RbfFactorization& f, RbfPrepareStats& stats, const ProgressFn& progress) {
    const auto n = static_cast<std::int64_t>(plan.num_centres());
    const int dim = plan.dim;
    const double inv_radius = 1.0 / plan.radius;
    const double* x = plan.centre_points.data();
    auto t0 = Clock::now();
    f.m.resize(n, n);
    const ProgressFn matrix_progress = progress_part(progress, 0, dense_matrix_share);
    ProgressCounter entries(matrix_progress, n * (n + 1) / 2);
    parallel_for(n, [&](std::int64_t j) {  // lower triangle, column j (contiguous)
        double* column = f.m.data() + j * n;
        for (std::int64_t i = j; i < n; ++i) column[i] = wendland_c2_r2(distance2(dim, x + i * dim, x + j * dim), inv_radius);
        entries.add(n - j);
    });
    stats.matrix_nonzeros = n * (n + 1) / 2;
    stats.matrix_seconds = seconds_since(t0);
    t0 = Clock::now();
    f.llt.emplace(f.m);
    if (f.llt->info() != Eigen::Success) throw Error(not_positive_definite(plan));
    stats.factor_seconds = seconds_since(t0);
    if (progress) progress(factor_share);
}

void factorize_sparse(const RbfPlan& plan, RbfFactorization& f, RbfPrepareStats& stats, const ProgressFn& progress) {
    const auto n = static_cast<std::int64_t>(plan.num_centres());
    const int dim = plan.dim;
    const double inv_radius = 1.0 / plan.radius;
    const double* x = plan.centre_points.data();
    auto t0 = Clock::now();
    // Column j of the lower triangle: the neighbours i >= j within R, in index order.
    std::vector<std::vector<Eigen::Triplet<double>>> columns(static_cast<std::size_t>(n));
    const ProgressFn matrix_progress = progress_part(progress, 0, sparse_matrix_share);
    ProgressCounter columns_done(matrix_progress, n);
    parallel_for_chunks(n, [&](std::int64_t begin, std::int64_t end) {
        std::vector<std::uint32_t> found;
        for (std::int64_t j = begin; j < end; ++j) {
            centres_within(*plan.index, x + j * dim, plan.radius, found);
            std::sort(found.begin(), found.end());
            auto& column = columns[static_cast<std::size_t>(j)];
            for (std::uint32_t i : found)
                if (static_cast<std::int64_t>(i) >= j)
                    column.emplace_back(static_cast<int>(i), static_cast<int>(j),
                                        wendland_c2_r2(distance2(dim, x + i * dim, x + j * dim), inv_radius));
            columns_done.add(1);
        }
    });
    std::vector<Eigen::Triplet<double>> triplets;
    for (const auto& column : columns) triplets.insert(triplets.end(), column.begin(), column.end());
    Eigen::SparseMatrix<double> m(n, n);
    m.setFromTriplets(triplets.begin(), triplets.end());
    stats.matrix_nonzeros = m.nonZeros();
    stats.matrix_seconds = seconds_since(t0);
    t0 = Clock::now();
    f.ldlt.compute(m);
    if (f.ldlt.info() != Eigen::Success || !(f.ldlt.vectorD().minCoeff() > 0)) throw Error(not_positive_definite(plan));
    const Eigen::SparseMatrix<double> l = f.ldlt.matrixL();
    f.sparse_factor_bytes = static_cast<std::size_t>(l.nonZeros()) * (sizeof(double) + sizeof(int)) +
                            static_cast<std::size_t>(n) * (sizeof(double) + 3 * sizeof(int));
    stats.factor_seconds = seconds_since(t0);
    if (progress) progress(factor_share);
}

}  // namespace

std::shared_ptr<const RbfFactorization> factorize_rbf(const RbfPlan& plan, RbfPrepareStats& stats,
                                                      const ProgressFn& progress) {
    auto f = std::make_shared<RbfFactorization>();
    f->dense = plan.dense;
    if (plan.dense) factorize_dense(plan, *f, stats, progress);
    else factorize_sparse(plan, *f, stats, progress);

    const auto t0 = Clock::now();
    const auto n = static_cast<std::int64_t>(plan.num_centres());
    const int np = plan.dim + 1;
    f->p.resize(n, np);
    for (std::int64_t i = 0; i < n; ++i) {
        double row[4];
        polynomial_row(plan, plan.centre_points.data() + i * plan.dim, row);
        for (int k = 0; k < np; ++k) f->p(i, k) = row[k];
    }
    f->g = f->solve(f->p);
    f->h.compute(f->p.transpose() * f->g);
    // H is singular exactly when P is rank deficient: all boundary nodes on a
    // line (2D) or plane (3D), where the linear polynomial is undetermined.
    if (f->h.info() != Eigen::Success || !(f->h.rcond() > 1e-13))
        throw MeshError("RBF: the boundary nodes are all " + std::string(plan.dim == 2 ? "collinear" : "coplanar") +
                        ", so the linear polynomial of the interpolant is undetermined");
    stats.factor_seconds += seconds_since(t0);
    stats.factor_bytes = factorization_bytes(*f);
    return f;
}

std::size_t factorization_bytes(const RbfFactorization& f) {
    const auto doubles = [](const Eigen::MatrixXd& a) { return static_cast<std::size_t>(a.size()) * sizeof(double); };
    return doubles(f.m) + f.sparse_factor_bytes + doubles(f.p) + doubles(f.g) + 16 * sizeof(double);
}

void solve_full(const RbfPlan& plan, std::span<const double> d, RbfCoefficients& c) {
    const RbfFactorization& f = *plan.factorization;
    const auto n = static_cast<Eigen::Index>(plan.num_centres());
    const int dim = plan.dim;
    const Eigen::MatrixXd rhs = Eigen::Map<const RowMajor>(d.data(), n, dim);
    const Eigen::MatrixXd y = f.solve(rhs);  // M⁻¹ d
    const Eigen::MatrixXd beta = f.h.solve(f.p.transpose() * y);
    const RowMajor alpha = y - f.g * beta;

    c.centres.resize(static_cast<std::size_t>(n));
    for (Eigen::Index i = 0; i < n; ++i) c.centres[static_cast<std::size_t>(i)] = static_cast<std::int32_t>(i);
    c.centre_points = plan.centre_points;
    c.alpha.assign(alpha.data(), alpha.data() + alpha.size());
    c.beta.resize(static_cast<std::size_t>((dim + 1) * dim));
    for (int k = 0; k <= dim; ++k)
        for (int j = 0; j < dim; ++j) c.beta[static_cast<std::size_t>(k * dim + j)] = beta(k, j);
    c.index = plan.index;
}

}  // namespace dgwarp
