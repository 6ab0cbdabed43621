// deform_idw: the O(N_b N_v) kernel of global IDW.
//
// Speed. Each volume node needs, per boundary node, a distance, one division
// and (odd exponents) one square root; these dominate. The kernel takes the
// volume nodes Lanes at a time and loops over the boundary nodes with the lane
// loop innermost, so the compiler turns the lane loop into SIMD arithmetic
// without reordering any node's sum (floating-point reductions are not
// vectorised without -ffast-math, and we want bit-reproducible results).
// Moving and static nodes are kept in separate structure-of-arrays lists,
// built once per step, so the inner loops have no branches: static nodes only
// add their weight to the denominator. The two loops are compiled for
// AVX-512, AVX2 and SSE2 (DGWARP_SIMD_CLONES), the CPU picking; this file is
// built with -fno-rounding-math -fno-math-errno -ffp-contract=off (see
// CMakeLists.txt). Integer exponents 1..8 are unrolled into multiplications
// (a template parameter); other exponents call std::pow.
// Each node's sums run over the boundary nodes in boundary order, whatever
// lane, block or thread the node falls in, so results do not depend on the
// thread count.
#include <algorithm>
#include <cmath>
#include <string>

#include "dgwarp/core/error.hpp"
#include "dgwarp/core/parallel_for.hpp"
#include "dgwarp/core/progress.hpp"
#include "dgwarp/core/simd_clones.hpp"
#include "dgwarp/methods/method_inputs.hpp"
#include "dgwarp/methods/boundary_set_tools.hpp"
#include "dgwarp/methods/idw.hpp"
#include "dgwarp/methods/rotation_series.hpp"

namespace dgwarp {

namespace {

constexpr int Lanes = 8;
// Added to every squared distance (in units of L): a volume node on top of a
// boundary node gets a huge but finite weight (1e12^16 at most) instead of
// inf / NaN. Beyond ρ = 1e-4 the sum rounds back to ρ² exactly. (An add, not
// a max: a max is compiled to a branch, which stops vectorisation.)
constexpr double min_distance2 = 1e-24;

// Per-step boundary data, structure of arrays. Coordinates are divided by L.
struct StepArrays {
    int dim = 2;
    std::int64_t num_moving = 0;
    std::int64_t num_static = 0;
    // Moving nodes: fields x (dim), t (dim), w (3), c (dim), each num_moving long.
    std::vector<double> moving;
    // Static nodes: x (dim), each num_static long.
    std::vector<double> fixed;
    double half_moving = 0;  // c_d / 2, for the std::pow path
    double half_static = 0;  // c_s / 2

    const double* moving_field(int f) const { return moving.data() + f * num_moving; }
    const double* static_field(int f) const { return fixed.data() + f * num_static; }
};

// Field indices in StepArrays::moving.
constexpr int field_x(int) { return 0; }
constexpr int field_t(int dim) { return dim; }
constexpr int field_w(int dim) { return 2 * dim; }
constexpr int field_c(int dim) { return 2 * dim + 3; }

StepArrays step_arrays(const IdwPlan& plan, const BoundaryMotion& motion, const IdwOptions& options, double l) {
    StepArrays a;
    const int dim = plan.dim;
    a.dim = dim;
    for (std::uint8_t m : plan.boundary_moving) (m ? a.num_moving : a.num_static) += 1;
    a.moving.resize(static_cast<std::size_t>((3 * dim + 3) * a.num_moving));
    a.fixed.resize(static_cast<std::size_t>(dim * a.num_static));
    a.half_moving = 0.5 * options.exponent_moving;
    a.half_static = 0.5 * options.exponent_static;
    const double inv_l = 1.0 / l;
    std::int64_t jm = 0, js = 0;
    for (std::size_t b = 0; b < plan.boundary_nodes.size(); ++b) {
        const double* x = plan.boundary_points.data() + b * dim;
        if (plan.boundary_moving[b]) {
            const NodeMotion& m = motion[b];
            for (int d = 0; d < dim; ++d) {
                a.moving[(field_x(dim) + d) * a.num_moving + jm] = x[d] * inv_l;
                a.moving[(field_t(dim) + d) * a.num_moving + jm] = m.translation[d];
                a.moving[(field_c(dim) + d) * a.num_moving + jm] = m.center[d];
            }
            for (int k = 0; k < 3; ++k) a.moving[(field_w(dim) + k) * a.num_moving + jm] = m.rotation[k];
            ++jm;
        } else {
            for (int d = 0; d < dim; ++d) a.fixed[d * a.num_static + js] = x[d] * inv_l;
            ++js;
        }
    }
    return a;
}

template <int K>
inline double power(double x) {
    if constexpr (K == 0) return 1.0;
    else return x * power<K - 1>(x);
}

// ρ^-E for ρ² = r2: E = 0 means "use half_exponent with std::pow".
template <int E>
inline double inverse_power(double r2, double half_exponent) {
    if constexpr (E == 0) return std::pow(r2, -half_exponent);
    else if constexpr (E % 2 == 0) return power<E / 2>(1.0 / r2);
    else return 1.0 / (power<(E - 1) / 2>(r2) * std::sqrt(r2));
}

// The sums of one block of Lanes volume nodes.
struct Sums {
    double den_moving[Lanes];
    double den_static[Lanes];
    double t[3][Lanes];
    double w[3][Lanes];
    double c[3][Lanes];
};

// Adds the moving nodes' terms to s. x: Dim × Lanes scaled coordinates.
template <int Dim, bool Rotate, int E>
DGWARP_SIMD_CLONES void moving_sums(const StepArrays& a, const double (&x)[3][Lanes], Sums& s) {
    constexpr int W = Dim == 2 ? 1 : 3;  // rotation components used (w_z in 2D)
    const double* bx[Dim];
    const double* bt[Dim];
    const double* bc[Dim];
    const double* bw[W];
    for (int d = 0; d < Dim; ++d) {
        bx[d] = a.moving_field(field_x(Dim) + d);
        bt[d] = a.moving_field(field_t(Dim) + d);
        bc[d] = a.moving_field(field_c(Dim) + d);
    }
    for (int k = 0; k < W; ++k) bw[k] = a.moving_field(field_w(Dim) + 3 - W + k);
    const double h = a.half_moving;
    double den[Lanes] = {}, t[Dim][Lanes] = {}, w[W][Lanes] = {}, c[Dim][Lanes] = {};
    for (std::int64_t j = 0; j < a.num_moving; ++j) {
        double p[Dim], tj[Dim], cj[Dim], wj[W];
        for (int d = 0; d < Dim; ++d) {
            p[d] = bx[d][j];
            tj[d] = bt[d][j];
            cj[d] = bc[d][j];
        }
        for (int k = 0; k < W; ++k) wj[k] = bw[k][j];
        for (int l = 0; l < Lanes; ++l) {
            double r2 = 0;
            for (int d = 0; d < Dim; ++d) r2 += (x[d][l] - p[d]) * (x[d][l] - p[d]);
            r2 += min_distance2;
            const double q = inverse_power<E>(r2, h);
            den[l] += q;
            for (int d = 0; d < Dim; ++d) t[d][l] += q * tj[d];
            if constexpr (Rotate) {
                for (int k = 0; k < W; ++k) w[k][l] += q * wj[k];
                for (int d = 0; d < Dim; ++d) c[d][l] += q * cj[d];
            }
        }
    }
    for (int l = 0; l < Lanes; ++l) {
        s.den_moving[l] = den[l];
        for (int d = 0; d < Dim; ++d) {
            s.t[d][l] = t[d][l];
            s.c[d][l] = c[d][l];
        }
        for (int k = 0; k < W; ++k) s.w[k][l] = w[k][l];
    }
}

// The static nodes' weight sum. x: Dim × Lanes scaled coordinates.
template <int Dim, int E>
DGWARP_SIMD_CLONES void static_sums(const StepArrays& a, const double (&x)[3][Lanes], Sums& s) {
    const double* bx[Dim];
    for (int d = 0; d < Dim; ++d) bx[d] = a.static_field(d);
    const double h = a.half_static;
    double den[Lanes] = {};
    for (std::int64_t j = 0; j < a.num_static; ++j) {
        double p[Dim];
        for (int d = 0; d < Dim; ++d) p[d] = bx[d][j];
        for (int l = 0; l < Lanes; ++l) {
            double r2 = 0;
            for (int d = 0; d < Dim; ++d) r2 += (x[d][l] - p[d]) * (x[d][l] - p[d]);
            r2 += min_distance2;
            den[l] += inverse_power<E>(r2, h);
        }
    }
    for (int l = 0; l < Lanes; ++l) s.den_static[l] = den[l];
}

using MovingSums = void (*)(const StepArrays&, const double (&)[3][Lanes], Sums&);
using StaticSums = void (*)(const StepArrays&, const double (&)[3][Lanes], Sums&);

// The exponent's template argument: itself for integers 1..8, else 0 (std::pow).
int exponent_case(double c) { return c == std::floor(c) && c >= 1 && c <= 8 ? static_cast<int>(c) : 0; }

template <int Dim, bool Rotate>
MovingSums pick_moving(double c) {
    switch (exponent_case(c)) {
        case 1: return moving_sums<Dim, Rotate, 1>;
        case 2: return moving_sums<Dim, Rotate, 2>;
        case 3: return moving_sums<Dim, Rotate, 3>;
        case 4: return moving_sums<Dim, Rotate, 4>;
        case 5: return moving_sums<Dim, Rotate, 5>;
        case 6: return moving_sums<Dim, Rotate, 6>;
        case 7: return moving_sums<Dim, Rotate, 7>;
        case 8: return moving_sums<Dim, Rotate, 8>;
        default: return moving_sums<Dim, Rotate, 0>;
    }
}

template <int Dim>
StaticSums pick_static(double c) {
    switch (exponent_case(c)) {
        case 1: return static_sums<Dim, 1>;
        case 2: return static_sums<Dim, 2>;
        case 3: return static_sums<Dim, 3>;
        case 4: return static_sums<Dim, 4>;
        case 5: return static_sums<Dim, 5>;
        case 6: return static_sums<Dim, 6>;
        case 7: return static_sums<Dim, 7>;
        case 8: return static_sums<Dim, 8>;
        default: return static_sums<Dim, 0>;
    }
}

// New position of volume node lane l from the sums (eq. 2.1 and x = c + R(w)(x0 - c) + t).
template <int Dim, bool Rotate>
void finish_node(const Sums& s, int l, const double* x0, double* y) {
    const double den_moving = s.den_moving[l];
    if (den_moving == 0) {  // no moving boundary node
        for (int d = 0; d < Dim; ++d) y[d] = x0[d];
        return;
    }
    const double den = den_moving + s.den_static[l];
    double t[Dim];
    for (int d = 0; d < Dim; ++d) t[d] = s.t[d][l] / den;
    if constexpr (!Rotate) {
        for (int d = 0; d < Dim; ++d) y[d] = x0[d] + t[d];
    } else {
        double e[Dim];  // x0 - c
        for (int d = 0; d < Dim; ++d) e[d] = x0[d] - s.c[d][l] / den_moving;
        if constexpr (Dim == 2) {
            const double w = s.w[0][l] / den;
            const RotationFactors r = rotation_factors(w * w);
            const double fw = r.f * w, gw2 = r.g * w * w;
            y[0] = x0[0] + (t[0] + (-fw * e[1] - gw2 * e[0]));
            y[1] = x0[1] + (t[1] + (fw * e[0] - gw2 * e[1]));
        } else {
            const double w[3] = {s.w[0][l] / den, s.w[1][l] / den, s.w[2][l] / den};
            const RotationFactors r = rotation_factors(w[0] * w[0] + w[1] * w[1] + w[2] * w[2]);
            const double we[3] = {w[1] * e[2] - w[2] * e[1], w[2] * e[0] - w[0] * e[2], w[0] * e[1] - w[1] * e[0]};
            const double wwe[3] = {w[1] * we[2] - w[2] * we[1], w[2] * we[0] - w[0] * we[2],
                                   w[0] * we[1] - w[1] * we[0]};
            for (int d = 0; d < 3; ++d) y[d] = x0[d] + (t[d] + (r.f * we[d] + r.g * wwe[d]));
        }
    }
}

// Moves volume nodes [v_begin, v_end).
template <int Dim, bool Rotate>
void deform_volume_range(const IdwPlan& plan, const StepArrays& a, MovingSums moving, StaticSums fixed,
                         double inv_l, const double* x0, double* out, std::int64_t v_begin, std::int64_t v_end) {
    VolumeNodeCursor cursor(plan.boundary_nodes, v_begin);
    Sums s;
    for (std::int64_t v = v_begin; v < v_end; v += Lanes) {
        const int count = static_cast<int>(std::min<std::int64_t>(Lanes, v_end - v));
        NodeId ids[Lanes];
        for (int l = 0; l < count; ++l) ids[l] = cursor.next();
        for (int l = count; l < Lanes; ++l) ids[l] = ids[count - 1];  // padding: repeat the last node
        double x[3][Lanes] = {};
        double x_own[Lanes][Dim];
        for (int l = 0; l < Lanes; ++l)
            for (int d = 0; d < Dim; ++d) {
                x_own[l][d] = x0[static_cast<std::int64_t>(ids[l]) * Dim + d];
                x[d][l] = x_own[l][d] * inv_l;
            }
        moving(a, x, s);
        fixed(a, x, s);
        for (int l = 0; l < count; ++l)
            finish_node<Dim, Rotate>(s, l, x_own[l], out + static_cast<std::int64_t>(ids[l]) * Dim);
    }
}

template <int Dim, bool Rotate>
void deform_volume(const IdwPlan& plan, const StepArrays& a, const IdwOptions& options, double inv_l,
                   const double* x0, double* out, ProgressCounter& progress) {
    const MovingSums moving = pick_moving<Dim, Rotate>(options.exponent_moving);
    const StaticSums fixed = pick_static<Dim>(options.exponent_static);
    // Each thread's chunk in blocks of progress_block nodes, a multiple of
    // Lanes: the nodes are grouped into lanes as without the blocks (and each
    // lane's sums are independent anyway).
    constexpr std::int64_t progress_block = 256 * Lanes;
    parallel_for_chunks(plan.num_volume_nodes(), [&](std::int64_t begin, std::int64_t end) {
        for (std::int64_t b = begin; b < end; b += progress_block) {
            const std::int64_t e = std::min(end, b + progress_block);
            deform_volume_range<Dim, Rotate>(plan, a, moving, fixed, inv_l, x0, out, b, e);
            progress.add(e - b);
        }
    });
}

}  // namespace

void deform_idw(const IdwPlan& plan, std::span<const double> points, const BoundaryMotion& motion,
                std::span<double> out, const IdwOptions& options, const ProgressFn& progress) {
    check_idw_options(options);
    check_step_arrays("IDW", plan.num_points, plan.dim, plan.boundary_nodes, points, motion, out);

    const double l = options.length_scale > 0 ? options.length_scale : plan.auto_length_scale;
    const StepArrays a = step_arrays(plan, motion, options, l);
    bool rotate = false;
    for (std::size_t b = 0; b < motion.size() && !rotate; ++b) {
        const Vec3& w = motion[b].rotation;
        rotate = plan.boundary_moving[b] && (w[2] != 0 || (plan.dim == 3 && (w[0] != 0 || w[1] != 0)));
    }

    // Volume nodes first: they read only their own coordinates, and the
    // boundary's from the plan, so `out` may alias `points`.
    const double inv_l = 1.0 / l;
    ProgressCounter moved(progress, plan.num_volume_nodes());
    if (plan.dim == 2) {
        if (rotate) deform_volume<2, true>(plan, a, options, inv_l, points.data(), out.data(), moved);
        else deform_volume<2, false>(plan, a, options, inv_l, points.data(), out.data(), moved);
    } else {
        if (rotate) deform_volume<3, true>(plan, a, options, inv_l, points.data(), out.data(), moved);
        else deform_volume<3, false>(plan, a, options, inv_l, points.data(), out.data(), moved);
    }
    const int dim = plan.dim;
    parallel_for(static_cast<std::int64_t>(plan.boundary_nodes.size()), [&](std::int64_t b) {
        const auto n = static_cast<std::size_t>(plan.boundary_nodes[b]);
        const std::span<const double> x = points.subspan(n * dim, dim);
        const std::span<double> y = out.subspan(n * dim, dim);
        if (plan.boundary_moving[b]) apply_motion(motion[b], x, y);
        else std::copy(x.begin(), x.end(), y.begin());
    });
    moved.finish();
}

}  // namespace dgwarp
