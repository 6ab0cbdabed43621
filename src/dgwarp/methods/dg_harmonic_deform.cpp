// deform_dg_harmonic: one harmonic solve on the coarse graph, then one pass over the nodes.
#include <algorithm>
#include <cmath>
#include <vector>

#include "dgwarp/core/parallel_for.hpp"
#include "dgwarp/core/prefetch.hpp"
#include "dgwarp/methods/boundary_mover.hpp"
#include "dgwarp/methods/dg_harmonic.hpp"
#include "dgwarp/methods/graph_vertex_motion.hpp"
#include "dgwarp/methods/method_inputs.hpp"
#include "dgwarp/methods/rotation_series.hpp"

namespace dgwarp {

namespace {

constexpr std::int64_t deform_block = 16384;

// Values carried per coarse vertex: t (Dim), w (W: 1 in 2D, 3 in 3D), the
// angle |w| and |w| c (Dim). The centre of a node is (|w| c) / |w|.
template <int Dim>
struct Layout {
    static constexpr int W = Dim == 2 ? 1 : 3;
    static constexpr int t = 0, w = Dim, angle = Dim + W, wc = Dim + W + 1;
    static constexpr int size = 2 * Dim + W + 1;
};

// Whether any boundary vertex translates, rotates.
struct Active {
    bool translation = false, rotation = false;
};

// The values of the boundary vertices (num_boundary_vertices × size).
template <int Dim>
Active boundary_values(const DgHarmonicPlan& plan, const BoundaryMotion& motion, double* g) {
    using L = Layout<Dim>;
    Active active;
    for (std::int32_t v = 0; v < plan.num_boundary_vertices; ++v) {
        double* x = g + static_cast<std::size_t>(v) * L::size;
        std::fill(x, x + L::size, 0.0);
        const std::int32_t b = plan.vertex_motion[v];
        if (b < 0) continue;
        const NodeMotion& m = motion[b];
        for (int d = 0; d < Dim; ++d) x[L::t + d] = m.translation[d];
        for (int j = 0; j < L::W; ++j) x[L::w + j] = m.rotation[3 - L::W + j];
        double a2 = 0;
        for (int j = 0; j < L::W; ++j) a2 += x[L::w + j] * x[L::w + j];
        const double angle = std::sqrt(a2);
        x[L::angle] = angle;
        for (int d = 0; d < Dim; ++d) x[L::wc + d] = angle * m.center[d];
        for (int d = 0; d < Dim; ++d) active.translation |= x[L::t + d] != 0;
        active.rotation |= angle != 0;
    }
    return active;
}

// Solves one system of `f` for the interior vertices' components
// [Offset, Offset + C) of `values` (num_vertices × K; the boundary vertices'
// rows are the data).
template <int K, int Offset, int C>
void solve_interior(const HarmonicFactors& f, const HarmonicFactors::System& sys, std::int32_t first_unknown,
                    double* values) {
    const std::int64_t n = f.num_unknowns();
    if (n == 0) return;
    std::vector<double> y(static_cast<std::size_t>(n) * C, 0.0);
    // Right-hand side B g, in the factor's order.
    for (std::int64_t i = 0; i < n; ++i) {
        double* r = y.data() + static_cast<std::size_t>(f.perm[i]) * C;
        for (std::int64_t p = f.coupling_start[i]; p < f.coupling_start[i + 1]; ++p) {
            const double w = sys.coupling_weight[p];
            const double* g = values + static_cast<std::size_t>(f.coupling_vertex[p]) * K + Offset;
            for (int k = 0; k < C; ++k) r[k] += w * g[k];
        }
    }
    // L z = y, z /= d, L^T x = z: all components at once, one pass over L each way.
    const std::int64_t* start = f.l_start.data();
    const std::int32_t* row = f.l_row.data();
    const double* lv = sys.l_value.data();
    for (std::int64_t j = 0; j < n; ++j) {
        const double* yj = y.data() + j * C;
        for (std::int64_t p = start[j]; p < start[j + 1]; ++p) {
            double* yi = y.data() + static_cast<std::int64_t>(row[p]) * C;
            const double l = lv[p];
            for (int k = 0; k < C; ++k) yi[k] -= l * yj[k];
        }
    }
    for (std::int64_t j = 0; j < n; ++j) {
        const double inv = 1.0 / sys.d[j];
        for (int k = 0; k < C; ++k) y[j * C + k] *= inv;
    }
    for (std::int64_t j = n - 1; j >= 0; --j) {
        double* yj = y.data() + j * C;
        double acc[C];
        for (int k = 0; k < C; ++k) acc[k] = yj[k];
        for (std::int64_t p = start[j]; p < start[j + 1]; ++p) {
            const double* yi = y.data() + static_cast<std::int64_t>(row[p]) * C;
            const double l = lv[p];
            for (int k = 0; k < C; ++k) acc[k] -= l * yi[k];
        }
        for (int k = 0; k < C; ++k) yj[k] = acc[k];
    }
    for (std::int64_t i = 0; i < n; ++i)
        std::copy_n(y.data() + static_cast<std::size_t>(f.perm[i]) * C, C,
                    values + static_cast<std::size_t>(first_unknown + i) * K + Offset);
}

// Prefetching, as in DG-IDW's step (dg_idw_deform.cpp): node -> coarse simplex
// row -> corner values are dependent loads, far apart in a spatially random
// node numbering; the loop asks for the row of the node row_prefetch_distance
// ahead and for the corner values of the node values_prefetch_distance ahead.
constexpr std::int64_t row_prefetch_distance = 16;
constexpr std::int64_t values_prefetch_distance = 4;

// Moves nodes [begin, end): boundary nodes by their own motion, volume nodes
// by the values interpolated in their coarse simplex. Rotates: whether any
// boundary node rotates (else only the translation is interpolated).
template <int Dim, bool Rotates>
void deform_range(const DgHarmonicPlan& plan, const double* x0, const NodeMotion* motion, const double* values,
                  double* out, std::int64_t begin, std::int64_t end) {
    using L = Layout<Dim>;
    constexpr int K = L::size, Corners = Dim + 1;
    std::int64_t vol = begin - (std::lower_bound(plan.boundary_nodes.begin(), plan.boundary_nodes.end(), begin) -
                                plan.boundary_nodes.begin());
    BoundaryMover<Dim> mover;
    const std::int32_t* node_simplex = plan.node_simplex.data();
    const std::int32_t* simplices = plan.simplices.data();
    constexpr std::size_t used_bytes = (Rotates ? K : Dim) * sizeof(double);  // t first in each row
    for (std::int64_t i = begin; i < end; ++i) {
        if (i + row_prefetch_distance < end && node_simplex[i + row_prefetch_distance] >= 0)
            prefetch_bytes(simplices + static_cast<std::int64_t>(node_simplex[i + row_prefetch_distance]) * Corners,
                           Corners * sizeof(std::int32_t));
        if (i + values_prefetch_distance < end && node_simplex[i + values_prefetch_distance] >= 0) {
            const std::int32_t* c =
                simplices + static_cast<std::int64_t>(node_simplex[i + values_prefetch_distance]) * Corners;
            for (int k = 0; k < Corners; ++k) prefetch_bytes(values + static_cast<std::size_t>(c[k]) * K, used_bytes);
        }
        const double* x = x0 + i * Dim;
        double* y = out + i * Dim;
        const std::int32_t s = plan.node_simplex[i];
        if (s < 0) {
            const std::int32_t b = -1 - s;
            if (plan.boundary_moving[b]) mover.move(motion[b], x, y);
            else std::copy(x, x + Dim, y);
            continue;
        }
        const double* e = plan.node_barycentric.data() + vol * Corners;
        ++vol;
        const std::int32_t* c = plan.simplices.data() + static_cast<std::int64_t>(s) * Corners;
        if constexpr (!Rotates) {
            double t[Dim] = {};
            for (int k = 0; k < Corners; ++k) {
                const double* vk = values + static_cast<std::size_t>(c[k]) * K + L::t;
                for (int d = 0; d < Dim; ++d) t[d] += e[k] * vk[d];
            }
            for (int d = 0; d < Dim; ++d) y[d] = x[d] + t[d];
            continue;
        }
        double v[K] = {};
        for (int k = 0; k < Corners; ++k) {
            const double* vk = values + static_cast<std::size_t>(c[k]) * K;
            for (int j = 0; j < K; ++j) v[j] += e[k] * vk[j];
        }
        const double* t = v + L::t;
        const double* w = v + L::w;
        double r[Dim];  // x0 - c
        const double inv_angle = v[L::angle] > 0 ? 1.0 / v[L::angle] : 0.0;
        for (int d = 0; d < Dim; ++d) r[d] = x[d] - v[L::wc + d] * inv_angle;
        if constexpr (Dim == 2) {
            const RotationFactors f = rotation_factors(w[0] * w[0]);
            const double fw = f.f * w[0], gw2 = f.g * w[0] * w[0];
            y[0] = x[0] + (t[0] + (-fw * r[1] - gw2 * r[0]));
            y[1] = x[1] + (t[1] + (fw * r[0] - gw2 * r[1]));
        } else {
            const RotationFactors f = rotation_factors(w[0] * w[0] + w[1] * w[1] + w[2] * w[2]);
            const double we[3] = {w[1] * r[2] - w[2] * r[1], w[2] * r[0] - w[0] * r[2], w[0] * r[1] - w[1] * r[0]};
            const double wwe[3] = {w[1] * we[2] - w[2] * we[1], w[2] * we[0] - w[0] * we[2], w[0] * we[1] - w[1] * we[0]};
            for (int d = 0; d < 3; ++d) y[d] = x[d] + (t[d] + (f.f * we[d] + f.g * wwe[d]));
        }
    }
}

template <int Dim>
void run(const DgHarmonicPlan& plan, std::span<const double> points, const BoundaryMotion& motion,
         std::span<double> out) {
    constexpr int K = Layout<Dim>::size;
    std::vector<double> values(static_cast<std::size_t>(plan.num_vertices()) * K);
    using L = Layout<Dim>;
    const Active active = boundary_values<Dim>(plan, motion, values.data());
    // A system whose data are all zero has the solution 0 (values start at 0).
    const HarmonicFactors& f = plan.solve;
    if (f.shared && active.translation && active.rotation) {
        solve_interior<K, 0, K>(f, f.translation, plan.num_boundary_vertices, values.data());  // one pass for all
    } else {
        if (active.translation) solve_interior<K, L::t, Dim>(f, f.translation, plan.num_boundary_vertices, values.data());
        if (active.rotation)
            solve_interior<K, L::w, K - Dim>(f, f.shared ? f.translation : f.rotation, plan.num_boundary_vertices,
                                             values.data());
    }
    parallel_for_blocks(plan.num_points(), deform_block, [&](std::int64_t begin, std::int64_t end) {
        if (active.rotation) deform_range<Dim, true>(plan, points.data(), motion.data(), values.data(), out.data(), begin, end);
        else deform_range<Dim, false>(plan, points.data(), motion.data(), values.data(), out.data(), begin, end);
    });
}

}  // namespace

DgHarmonicStepReport deform_dg_harmonic(const DgHarmonicPlan& plan, std::span<const double> points,
                                        const BoundaryMotion& motion, std::span<double> out) {
    check_step_arrays("DG-harmonic", plan.num_points(), plan.dim, plan.boundary_nodes, points, motion, out);
    if (plan.dim == 2) run<2>(plan, points, motion, out);
    else run<3>(plan, points, motion, out);
    return {count_conflicting_shared_vertices(plan.shared_offsets, plan.shared_members, plan.boundary_moving, motion)};
}

}  // namespace dgwarp
