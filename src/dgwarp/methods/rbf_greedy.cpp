// Greedy data reduction (Rendall & Allen 2009) for the RBF interpolant of
// one motion. The centres' matrix M_C = L Lᵀ grows by one row per added
// centre (an O(n²) update of the Cholesky factor L); with Z_P = L⁻¹ P_C and
// Z_d = L⁻¹ d_C, which also grow by one row, the polynomial is eliminated as
// in the full system:
//   H = Z_Pᵀ Z_P,  β = H⁻¹ Z_Pᵀ Z_d,  α = L⁻ᵀ (Z_d - Z_P β).
// The φ values between every boundary node and each centre are kept
// (num_boundary × n), so the boundary errors cost one pass over them.
#include <Eigen/Cholesky>
#include <Eigen/Dense>
#include <cmath>
#include <string>
#include <vector>

#include "dgwarp/core/error.hpp"
#include "dgwarp/core/parallel_for.hpp"
#include "dgwarp/methods/rbf_centre_index.hpp"
#include "dgwarp/methods/rbf_internal.hpp"

namespace dgwarp {

namespace {

// A new centre whose Cholesky pivot² falls below this (φ(0) = 1) is
// numerically a combination of the others: the greedy loop stops there.
constexpr double min_pivot2 = 1e-14;
// Boundary nodes × centres above which the error pass runs in parallel.
constexpr std::size_t parallel_work = 200000;

/// The state of the greedy loop: the centres chosen so far, the factors and
/// the coefficients for them (see the file comment).
struct Greedy {
    const RbfPlan& plan;
    std::span<const double> d;   // num_boundary × dim
    int dim;
    int np;                      // dim + 1
    std::size_t nb;              // boundary nodes
    double inv_radius;
    std::vector<std::int32_t> centres{};
    std::vector<std::uint8_t> is_centre{};
    std::vector<double> l{};       // L, packed by rows: row i holds i + 1 entries from i (i + 1) / 2
    std::vector<double> zp{};      // n × np, row-major
    std::vector<double> zd{};      // n × dim, row-major
    std::vector<double> phi{};     // column j (nb values): φ between every boundary node and centre j
    std::vector<double> alpha{};   // n × dim, row-major
    std::vector<double> beta{};    // np × dim, row-major
    std::vector<double> error{};   // |s(x_b) - d_b| per boundary node

    const double* x(std::size_t b) const { return plan.centre_points.data() + b * dim; }
};

/// The index of the largest value (the first on ties).
std::size_t index_of_largest(const std::vector<double>& v) {
    std::size_t largest = 0;
    for (std::size_t i = 1; i < v.size(); ++i)
        if (v[i] > v[largest]) largest = i;
    return largest;
}

/// Adds boundary node k as a centre; false when it is numerically dependent.
bool add_centre(Greedy& g, std::size_t k) {
    const std::size_t n = g.centres.size(), nb = g.nb;
    const int dim = g.dim, np = g.np;
    const std::size_t needed = (nb * (n + 1) + (n + 1) * (n + 2) / 2 + (n + 1) * (np + 2 * dim)) * sizeof(double);
    check_dense_bytes(needed, g.plan.max_dense_bytes,
                      "the greedy reduction's arrays for " + std::to_string(n + 1) + " centres and " +
                          std::to_string(nb) + " boundary nodes");
    g.phi.resize(nb * (n + 1));
    double* column = g.phi.data() + n * nb;
    for (std::size_t b = 0; b < nb; ++b) column[b] = wendland_c2_r2(distance2(dim, g.x(b), g.x(k)), g.inv_radius);
    // Row n of L: L[0..n) r = m, m_i = φ(|x_ci - x_k|), pivot² = φ(0) - r·r.
    std::vector<double> r(n);
    double rr = 0;
    for (std::size_t i = 0; i < n; ++i) {
        const double* li = g.l.data() + i * (i + 1) / 2;
        double s = column[static_cast<std::size_t>(g.centres[i])];
        for (std::size_t j = 0; j < i; ++j) s -= li[j] * r[j];
        r[i] = s / li[i];
        rr += r[i] * r[i];
    }
    const double pivot2 = 1.0 - rr;
    if (!(pivot2 > min_pivot2)) {
        g.phi.resize(nb * n);
        return false;
    }
    const double pivot = std::sqrt(pivot2);
    g.l.insert(g.l.end(), r.begin(), r.end());
    g.l.push_back(pivot);
    double prow[4];
    polynomial_row(g.plan, g.x(k), prow);
    for (int c = 0; c < np; ++c) {
        double s = prow[c];
        for (std::size_t i = 0; i < n; ++i) s -= r[i] * g.zp[i * np + c];
        g.zp.push_back(s / pivot);
    }
    for (int c = 0; c < dim; ++c) {
        double s = g.d[k * dim + c];
        for (std::size_t i = 0; i < n; ++i) s -= r[i] * g.zd[i * dim + c];
        g.zd.push_back(s / pivot);
    }
    g.centres.push_back(static_cast<std::int32_t>(k));
    g.is_centre[k] = 1;
    return true;
}

/// α and β for the current centres (needs at least np affinely independent ones).
void solve_coefficients(Greedy& g) {
    const std::size_t n = g.centres.size();
    const int dim = g.dim, np = g.np;
    Eigen::MatrixXd h = Eigen::MatrixXd::Zero(np, np), rhs = Eigen::MatrixXd::Zero(np, dim);
    for (std::size_t i = 0; i < n; ++i)
        for (int a = 0; a < np; ++a) {
            for (int b = 0; b < np; ++b) h(a, b) += g.zp[i * np + a] * g.zp[i * np + b];
            for (int c = 0; c < dim; ++c) rhs(a, c) += g.zp[i * np + a] * g.zd[i * dim + c];
        }
    const Eigen::MatrixXd b = h.llt().solve(rhs);
    g.beta.assign(static_cast<std::size_t>(np * dim), 0.0);
    for (int a = 0; a < np; ++a)
        for (int c = 0; c < dim; ++c) g.beta[a * dim + c] = b(a, c);
    // w = Z_d - Z_P β, then α = L⁻ᵀ w (backward substitution; L's column i is row i of Lᵀ).
    g.alpha.assign(n * dim, 0.0);
    for (std::size_t i = 0; i < n; ++i)
        for (int c = 0; c < dim; ++c) {
            double s = g.zd[i * dim + c];
            for (int a = 0; a < np; ++a) s -= g.zp[i * np + a] * g.beta[a * dim + c];
            g.alpha[i * dim + c] = s;
        }
    for (std::size_t i = n; i-- > 0;) {
        const double lii = g.l[i * (i + 1) / 2 + i];
        for (int c = 0; c < dim; ++c) g.alpha[i * dim + c] /= lii;
        for (std::size_t j = 0; j < i; ++j) {  // subtract L_ij α_i from the rows above
            const double lij = g.l[i * (i + 1) / 2 + j];
            for (int c = 0; c < dim; ++c) g.alpha[j * dim + c] -= lij * g.alpha[i * dim + c];
        }
    }
}

/// error_b = |s(x_b) - d_b| for every boundary node; returns the largest's index.
std::size_t update_errors(Greedy& g) {
    const std::size_t n = g.centres.size(), nb = g.nb;
    const int dim = g.dim, np = g.np;
    const auto chunk = [&](std::int64_t begin, std::int64_t end) {
        std::vector<double> s(static_cast<std::size_t>((end - begin) * dim));
        for (std::int64_t b = begin; b < end; ++b) {
            double prow[4];
            polynomial_row(g.plan, g.x(static_cast<std::size_t>(b)), prow);
            for (int c = 0; c < dim; ++c) {
                double v = 0;
                for (int a = 0; a < np; ++a) v += prow[a] * g.beta[a * dim + c];
                s[(b - begin) * dim + c] = v;
            }
        }
        for (std::size_t j = 0; j < n; ++j) {
            const double* column = g.phi.data() + j * nb;
            for (std::int64_t b = begin; b < end; ++b)
                for (int c = 0; c < dim; ++c) s[(b - begin) * dim + c] += column[b] * g.alpha[j * dim + c];
        }
        for (std::int64_t b = begin; b < end; ++b) {
            double e2 = 0;
            for (int c = 0; c < dim; ++c) {
                const double e = s[(b - begin) * dim + c] - g.d[b * dim + c];
                e2 += e * e;
            }
            g.error[b] = std::sqrt(e2);
        }
    };
    // Threads only pay off for large passes (a parallel region costs
    // microseconds, far more on a loaded machine, and there is one per centre).
    if (nb * n > parallel_work) parallel_for_chunks(static_cast<std::int64_t>(nb), chunk);
    else chunk(0, static_cast<std::int64_t>(nb));
    return index_of_largest(g.error);
}

/// Squared distance of x(b) from the affine hull of the current centres (up to 3 of them).
double hull_distance2(const Greedy& g, std::size_t b) {
    const std::size_t n = g.centres.size();
    const int dim = g.dim;
    const double* a = g.x(static_cast<std::size_t>(g.centres[0]));
    double v[3] = {}, e1[3] = {}, e2[3] = {};
    for (int k = 0; k < dim; ++k) v[k] = g.x(b)[k] - a[k];
    if (n == 1) return v[0] * v[0] + v[1] * v[1] + v[2] * v[2];
    for (int k = 0; k < dim; ++k) e1[k] = g.x(static_cast<std::size_t>(g.centres[1]))[k] - a[k];
    auto cross = [](const double* p, const double* q, double* out) {
        out[0] = p[1] * q[2] - p[2] * q[1];
        out[1] = p[2] * q[0] - p[0] * q[2];
        out[2] = p[0] * q[1] - p[1] * q[0];
    };
    auto dot = [](const double* p, const double* q) { return p[0] * q[0] + p[1] * q[1] + p[2] * q[2]; };
    if (n == 2) {  // distance from the line: |e1 × v|² / |e1|²
        double c[3];
        cross(e1, v, c);
        return dot(c, c) / dot(e1, e1);
    }
    for (int k = 0; k < dim; ++k) e2[k] = g.x(static_cast<std::size_t>(g.centres[2]))[k] - a[k];
    double normal[3];  // n == 3 (3D): distance from the plane
    cross(e1, e2, normal);
    const double h = dot(normal, v);
    return h * h / dot(normal, normal);
}

/// The first dim + 1 centres: node `worst` (the largest displacement), then
/// dim nodes each farthest from the affine hull of the centres so far, so that
/// the linear polynomial is determined. Throws MeshError when the boundary
/// nodes are all on one line (2D) or plane (3D).
void seed_centres(Greedy& g, std::size_t worst) {
    add_centre(g, worst);
    for (int s = 0; s < g.dim; ++s) {
        std::size_t far = 0;
        double far2 = -1;
        for (std::size_t b = 0; b < g.nb; ++b) {
            const double h2 = g.is_centre[b] ? -1 : hull_distance2(g, b);
            if (h2 > far2) {
                far2 = h2;
                far = b;
            }
        }
        if (!(far2 > 1e-18 * g.plan.diagonal * g.plan.diagonal) || !add_centre(g, far))
            throw MeshError("RBF: the boundary nodes are all " + std::string(g.dim == 2 ? "collinear" : "coplanar") +
                            ", so the linear polynomial of the interpolant is undetermined");
    }
}

}  // namespace

void solve_greedy(const RbfPlan& plan, std::span<const double> d, RbfCoefficients& c) {
    const int dim = plan.dim;
    Greedy g{plan, d, dim, dim + 1, plan.num_centres(), 1.0 / plan.radius};
    g.is_centre.assign(g.nb, 0);
    g.error.resize(g.nb);
    for (std::size_t b = 0; b < g.nb; ++b) {
        double e2 = 0;
        for (int k = 0; k < dim; ++k) e2 += d[b * dim + k] * d[b * dim + k];
        g.error[b] = std::sqrt(e2);
    }
    std::size_t worst = index_of_largest(g.error);
    double max_error = g.error[worst];
    g.beta.assign(static_cast<std::size_t>((dim + 1) * dim), 0.0);
    if (max_error > plan.greedy_tolerance) {
        seed_centres(g, worst);
        // Add the node of the largest error until every error is within the tolerance.
        while (true) {
            solve_coefficients(g);
            worst = update_errors(g);
            max_error = g.error[worst];
            if (max_error <= plan.greedy_tolerance || g.centres.size() == g.nb || g.is_centre[worst] ||
                !add_centre(g, worst))
                break;
        }
    }

    const std::size_t n = g.centres.size();
    c.centres = g.centres;
    c.centre_points.resize(n * dim);
    for (std::size_t i = 0; i < n; ++i)
        for (int k = 0; k < dim; ++k) c.centre_points[i * dim + k] = g.x(static_cast<std::size_t>(g.centres[i]))[k];
    c.alpha = g.alpha;
    c.alpha.resize(n * dim, 0.0);
    c.beta = g.beta;
    c.index = plan.compact && n > 0 ? build_centre_index(dim, c.centre_points) : nullptr;
    c.report.centres = static_cast<std::int64_t>(n);
    c.report.boundary_error = max_error;
}

}  // namespace dgwarp
