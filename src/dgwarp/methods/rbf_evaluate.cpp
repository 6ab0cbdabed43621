// Evaluating an RBF interpolant: s(x) = Σ_j α_j φ(|x - x_j| / R) + p(x).
// Global support: every centre contributes, and the loop is laid out like
// IDW's (idw_deform.cpp): points Lanes at a time, centres in structure-of-
// arrays form, the lane loop innermost so it becomes SIMD arithmetic without
// reordering any point's sum, compiled for AVX-512 / AVX2 / SSE2. Compact
// support: the centres within R from the k-d tree, summed in the tree's
// traversal order. Either way each point's sum has a fixed order, so results
// do not depend on the thread count.
#include <algorithm>
#include <string>

#include "dgwarp/core/error.hpp"
#include "dgwarp/core/parallel_for.hpp"
#include "dgwarp/core/simd_clones.hpp"
#include "dgwarp/methods/boundary_set_tools.hpp"
#include "dgwarp/methods/rbf_centre_index.hpp"
#include "dgwarp/methods/rbf_internal.hpp"

namespace dgwarp {

namespace {

constexpr int Lanes = 8;

// The centres in structure-of-arrays form: coordinate k of centre j at
// x[k * n + j], component k of α_j at alpha[k * n + j].
struct CentreArrays {
    std::int64_t n = 0;
    std::vector<double> x;
    std::vector<double> alpha;
};

CentreArrays centre_arrays(int dim, const RbfCoefficients& c) {
    CentreArrays a;
    a.n = static_cast<std::int64_t>(c.centres.size());
    a.x.resize(static_cast<std::size_t>(a.n * dim));
    a.alpha.resize(static_cast<std::size_t>(a.n * dim));
    for (std::int64_t j = 0; j < a.n; ++j)
        for (int k = 0; k < dim; ++k) {
            a.x[k * a.n + j] = c.centre_points[j * dim + k];
            a.alpha[k * a.n + j] = c.alpha[j * dim + k];
        }
    return a;
}

// s[k][l] = Σ_j α_jk φ(|x_l - x_j| / R) over all centres, for Lanes points x[.][l].
template <int Dim>
DGWARP_SIMD_CLONES void global_sums(const CentreArrays& a, double inv_radius, const double (&x)[3][Lanes],
                                    double (&s)[3][Lanes]) {
    const double* cx[Dim];
    const double* ca[Dim];
    for (int k = 0; k < Dim; ++k) {
        cx[k] = a.x.data() + k * a.n;
        ca[k] = a.alpha.data() + k * a.n;
    }
    double sum[Dim][Lanes] = {};
    for (std::int64_t j = 0; j < a.n; ++j) {
        double p[Dim], aj[Dim];
        for (int k = 0; k < Dim; ++k) {
            p[k] = cx[k][j];
            aj[k] = ca[k][j];
        }
        for (int l = 0; l < Lanes; ++l) {
            double r2 = 0;
            for (int k = 0; k < Dim; ++k) r2 += (x[k][l] - p[k]) * (x[k][l] - p[k]);
            const double phi = wendland_c2_r2(r2, inv_radius);
            for (int k = 0; k < Dim; ++k) sum[k][l] += phi * aj[k];
        }
    }
    for (int k = 0; k < Dim; ++k)
        for (int l = 0; l < Lanes; ++l) s[k][l] = sum[k][l];
}

// Evaluates s at points given by `point(i)` (a pointer to dim coordinates)
// for i in [begin, end), writing through `write(i, s)`; `count` points in all.
class Evaluator {
public:
    Evaluator(const RbfPlan& plan, const RbfCoefficients& c)
        : plan_(plan), c_(c), dim_(plan.dim), inv_radius_(1.0 / plan.radius),
          compact_(plan.compact && c.index != nullptr) {
        if (!compact_) arrays_ = centre_arrays(dim_, c);
    }

    // s at up to Lanes points xs[l] (count of them), into s[l * dim + k].
    void block(const double* const* xs, int count, double* s, std::vector<std::uint32_t>& found) const {
        if (compact_) {
            for (int l = 0; l < count; ++l) compact_point(xs[l], s + l * dim_, found);
        } else {
            double x[3][Lanes] = {}, sum[3][Lanes];
            for (int l = 0; l < Lanes; ++l)
                for (int k = 0; k < dim_; ++k) x[k][l] = xs[std::min(l, count - 1)][k];  // padding repeats the last
            if (dim_ == 2) global_sums<2>(arrays_, inv_radius_, x, sum);
            else global_sums<3>(arrays_, inv_radius_, x, sum);
            for (int l = 0; l < count; ++l)
                for (int k = 0; k < dim_; ++k) s[l * dim_ + k] = sum[k][l];
        }
        for (int l = 0; l < count; ++l) add_polynomial(xs[l], s + l * dim_);
    }

private:
    void compact_point(const double* x, double* s, std::vector<std::uint32_t>& found) const {
        for (int k = 0; k < dim_; ++k) s[k] = 0;
        centres_within(*c_.index, x, plan_.radius, found);
        for (std::uint32_t j : found) {
            const double phi = wendland_c2_r2(distance2(dim_, x, c_.centre_points.data() + j * dim_), inv_radius_);
            for (int k = 0; k < dim_; ++k) s[k] += phi * c_.alpha[j * dim_ + k];
        }
    }

    void add_polynomial(const double* x, double* s) const {
        double row[4];
        polynomial_row(plan_, x, row);
        for (int k = 0; k < dim_; ++k) {
            double p = 0;
            for (int a = 0; a <= dim_; ++a) p += row[a] * c_.beta[a * dim_ + k];
            s[k] += p;
        }
    }

    const RbfPlan& plan_;
    const RbfCoefficients& c_;
    int dim_;
    double inv_radius_;
    bool compact_;
    CentreArrays arrays_;
};

}  // namespace

void evaluate_rbf(const RbfPlan& plan, const RbfCoefficients& c, std::span<const double> x,
                  std::span<double> displacement) {
    const int dim = plan.dim;
    if (c.dim != dim || c.alpha.size() != c.centres.size() * dim || c.centre_points.size() != c.alpha.size() ||
        c.beta.size() != static_cast<std::size_t>((dim + 1) * dim))
        throw MeshError("RBF: the coefficients do not fit the plan (" + std::to_string(c.dim) + "D, " +
                        std::to_string(c.centres.size()) + " centres)");
    if (x.size() % dim != 0 || displacement.size() != x.size())
        throw MeshError("RBF: evaluate_rbf got " + std::to_string(x.size()) + " coordinates and room for " +
                        std::to_string(displacement.size()) + " (expected equal sizes, a multiple of " +
                        std::to_string(dim) + ")");
    const Evaluator e(plan, c);
    const auto n = static_cast<std::int64_t>(x.size() / dim);
    parallel_for_chunks(n, [&](std::int64_t begin, std::int64_t end) {
        std::vector<std::uint32_t> found;
        const double* xs[Lanes];
        for (std::int64_t i = begin; i < end; i += Lanes) {
            const int count = static_cast<int>(std::min<std::int64_t>(Lanes, end - i));
            for (int l = 0; l < count; ++l) xs[l] = x.data() + (i + l) * dim;
            e.block(xs, count, displacement.data() + i * dim, found);
        }
    });
}

void move_volume_nodes(const RbfPlan& plan, const RbfCoefficients& c, std::span<const double> points,
                       std::span<double> out, ProgressCounter& moved) {
    const int dim = plan.dim;
    const Evaluator e(plan, c);
    // Nodes per progress report, a multiple of Lanes: the lanes are grouped
    // as without reports (and each point's sum is independent anyway).
    constexpr std::int64_t progress_block = 256 * Lanes;
    parallel_for_chunks(plan.num_volume_nodes(), [&](std::int64_t begin, std::int64_t end) {
        std::vector<std::uint32_t> found;
        VolumeNodeCursor cursor(plan.boundary_nodes, begin);
        for (std::int64_t v = begin; v < end; v += Lanes) {
            if (v > begin && (v - begin) % progress_block == 0) moved.add(progress_block);
            const int count = static_cast<int>(std::min<std::int64_t>(Lanes, end - v));
            NodeId ids[Lanes];
            double x0[Lanes][3];  // copies: `out` may alias `points`
            const double* xs[Lanes];
            for (int l = 0; l < count; ++l) {
                ids[l] = cursor.next();
                for (int k = 0; k < dim; ++k) x0[l][k] = points[static_cast<std::size_t>(ids[l]) * dim + k];
                xs[l] = x0[l];
            }
            double s[Lanes * 3];
            e.block(xs, count, s, found);
            for (int l = 0; l < count; ++l)
                for (int k = 0; k < dim; ++k)
                    out[static_cast<std::size_t>(ids[l]) * dim + k] = x0[l][k] + s[l * dim + k];
        }
        moved.add((end - begin - 1) % progress_block + 1);  // the last block's nodes
    });
}

}  // namespace dgwarp
