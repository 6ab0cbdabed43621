// deform_dg_idw: one pass over the nodes per step.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <string>

#include "dgwarp/core/error.hpp"
#include "dgwarp/core/parallel_for.hpp"
#include "dgwarp/core/prefetch.hpp"
#include "dgwarp/methods/method_inputs.hpp"
#include "dgwarp/methods/boundary_mover.hpp"
#include "dgwarp/methods/dg_idw.hpp"
#include "dgwarp/methods/dg_idw_checks.hpp"
#include "dgwarp/methods/dg_idw_step.hpp"
#include "dgwarp/methods/graph_vertex_motion.hpp"
#include "dgwarp/methods/rotation_series.hpp"

namespace dgwarp {

namespace {

// Nodes per block of the threaded loop: large enough that handing out a block
// costs nothing against it, small enough (~50 blocks at 800k nodes) to balance.
constexpr std::int64_t deform_block = 16384;

// Per-step constants: sigma = 1 / (1 + rho * k) with k = 1 / (a L) (dg_idw.hpp).
struct StepConstants {
    double k_t;  // 1 / (a_translation L)
    double k_r;  // 1 / (a_rotation L)
};


// The rotation factors with a series of Terms terms; 10: any angle.
template <int Terms>
RotationFactors factors(double angle2) {
    if constexpr (Terms >= 10) {
        return rotation_factors(angle2);
    } else {
        return rotation_factors_series<Terms>(angle2);
    }
}

// One volume node x (dim coordinates) in a simplex whose first Moving corners
// move: y = x0 + t + (R(w) - I)(x0 - c), with the coefficients v of dg_idw.hpp
// (moving slots qhat, static slots -m u / P). No branch per corner.
template <int Dim, int Terms, int Moving>
inline void interpolate(const double* x, double* y, const double* v, const std::int32_t* corner,
                        const NodeMotion* motion, double k_t, double k_r) {
    constexpr int Corners = Dim + 1;
    double q_sum = 0, rho = 0;
    for (int k = 0; k < Moving; ++k) q_sum += v[k];
    for (int k = Moving; k < Corners; ++k) rho -= v[k];
    if (q_sum == 0) {  // on a static graph vertex
        for (int d = 0; d < Dim; ++d) y[d] = x[d];
        return;
    }
    const NodeMotion* mk[Moving];
    for (int k = 0; k < Moving; ++k) mk[k] = motion + corner[k];
    const double sigma_t = 1.0 / (1.0 + rho * k_t);
    double t[Dim] = {};
    for (int k = 0; k < Moving; ++k)
        for (int d = 0; d < Dim; ++d) t[d] += v[k] * mk[k]->translation[d];
    if constexpr (Terms == 0) {
        for (int d = 0; d < Dim; ++d) y[d] = x[d] + sigma_t * t[d];
    } else {
        const double sigma_r = 1.0 / (1.0 + rho * k_r);
        constexpr int W = Dim == 2 ? 1 : 3;  // rotation components: w_z in 2D
        double w[W] = {}, c[Dim] = {};
        for (int k = 0; k < Moving; ++k) {
            for (int j = 0; j < W; ++j) w[j] += v[k] * mk[k]->rotation[3 - W + j];
            for (int d = 0; d < Dim; ++d) c[d] += v[k] * mk[k]->center[d];
        }
        for (int j = 0; j < W; ++j) w[j] *= sigma_r;
        double e[Dim];  // x0 - c
        for (int d = 0; d < Dim; ++d) e[d] = x[d] - c[d];
        if constexpr (Dim == 2) {
            const RotationFactors r = factors<Terms>(w[0] * w[0]);
            const double fw = r.f * w[0], gw2 = r.g * w[0] * w[0];
            y[0] = x[0] + (sigma_t * t[0] + (-fw * e[1] - gw2 * e[0]));
            y[1] = x[1] + (sigma_t * t[1] + (fw * e[0] - gw2 * e[1]));
        } else {
            const RotationFactors r = factors<Terms>(w[0] * w[0] + w[1] * w[1] + w[2] * w[2]);
            const double we[3] = {w[1] * e[2] - w[2] * e[1], w[2] * e[0] - w[0] * e[2], w[0] * e[1] - w[1] * e[0]};
            const double wwe[3] = {w[1] * we[2] - w[2] * we[1], w[2] * we[0] - w[0] * we[2], w[0] * we[1] - w[1] * we[0]};
            for (int d = 0; d < 3; ++d) y[d] = x[d] + (sigma_t * t[d] + (r.f * we[d] + r.g * wwe[d]));
        }
    }
}

// Prefetching. In a spatially random node numbering (Gmsh's 3D Delaunay)
// each node's simplex row and its corners' motions are far from the previous
// node's, and the loads depend on each other (node -> row -> motions): without
// help every node waits for two cache misses in turn (the step took 2-3x as
// long as on the same mesh renumbered). The node -> simplex array is read in
// order, so the loop asks for the row of the node row_prefetch_distance ahead,
// and for the corner motions of the node motion_prefetch_distance ahead
// (whose row has arrived by then). Measured on the 826k sphere (1 thread,
// CPU time under load): Gmsh's numbering 37.5 -> 20.9 ms, renumbered 16.7 ->
// 16.2 ms; distances 8/4, 16/8, 24/12, 32/16 were slower in one or the other.
constexpr std::int64_t row_prefetch_distance = 16;
constexpr std::int64_t motion_prefetch_distance = 4;

inline void prefetch_row(const std::int32_t* node_simplex, const std::int32_t* simplex_motion, int corners,
                         std::int64_t i) {
    const std::int32_t s = node_simplex[i];
    if (s >= 0) __builtin_prefetch(simplex_motion + static_cast<std::int64_t>(s) * corners);
}

inline void prefetch_corner_motions(const std::int32_t* node_simplex, const std::int32_t* simplex_motion, int corners,
                                    const NodeMotion* motion, std::int64_t i) {
    const std::int32_t s = node_simplex[i];
    if (s < 0) return;
    const std::int32_t* corner = simplex_motion + static_cast<std::int64_t>(s) * corners;
    for (int k = 0; k < corners && corner[k] >= 0; ++k)  // the moving corners (first in the row)
        prefetch_bytes(motion + corner[k], sizeof(NodeMotion));
}

// Moves nodes [begin, end): boundary nodes by their own motion, volume nodes
// by the interpolated one. Terms: 0 when no moving boundary node rotates,
// else the Taylor terms of the rotation factors (10: any angle).
template <int Dim, int Terms>
void deform_range(const DgIdwPlan& plan, const double* x0, const NodeMotion* motion, double* out,
                  const StepConstants& sc, std::int64_t begin, std::int64_t end) {
    constexpr int Corners = Dim + 1;
    // Volume index of the first volume node at or after `begin`.
    std::int64_t vol = begin - (std::lower_bound(plan.boundary_nodes.begin(), plan.boundary_nodes.end(), begin) -
                                plan.boundary_nodes.begin());
    const std::int32_t* node_simplex = plan.node_simplex.data();
    const std::int32_t* simplex_motion = plan.simplex_motion.data();
    const double* coefficients = plan.node_coefficients.data();
    const std::uint8_t* boundary_moving = plan.boundary_moving.data();
    const double k_t = sc.k_t, k_r = sc.k_r;  // locals: stores to out cannot change them
    BoundaryMover<Dim> boundary_mover;
    for (std::int64_t i = begin; i < end; ++i) {
        if (i + row_prefetch_distance < end) prefetch_row(node_simplex, simplex_motion, Corners, i + row_prefetch_distance);
        if (i + motion_prefetch_distance < end)
            prefetch_corner_motions(node_simplex, simplex_motion, Corners, motion, i + motion_prefetch_distance);
        const double* x = x0 + i * Dim;
        double* y = out + i * Dim;
        const std::int32_t s = node_simplex[i];
        if (s < 0) {
            const std::int32_t b = -1 - s;
            if (boundary_moving[b]) {
                boundary_mover.move(motion[b], x, y);
            } else {
                for (int d = 0; d < Dim; ++d) y[d] = x[d];
            }
            continue;
        }
        const double* v = coefficients + vol * Corners;
        ++vol;
        const std::int32_t* corner = simplex_motion + static_cast<std::int64_t>(s) * Corners;
        int moving = 0;  // moving corners come first in the row
        for (int k = 0; k < Corners; ++k) moving += corner[k] >= 0;
        switch (moving) {
            case 0: for (int d = 0; d < Dim; ++d) y[d] = x[d]; break;
            case 1: interpolate<Dim, Terms, 1>(x, y, v, corner, motion, k_t, k_r); break;
            case 2: interpolate<Dim, Terms, 2>(x, y, v, corner, motion, k_t, k_r); break;
            case 3: interpolate<Dim, Terms, 3>(x, y, v, corner, motion, k_t, k_r); break;
            default: interpolate<Dim, Terms, Dim + 1>(x, y, v, corner, motion, k_t, k_r); break;
        }
    }
}

}  // namespace

void check_dg_idw_options(const DgIdwOptions& options) {
    auto positive = [](double a) { return std::isfinite(a) && a > 0; };
    if (!positive(options.a_translation) || !positive(options.a_rotation))
        throw Error("DG-IDW: a_translation and a_rotation must be finite and positive, got " +
                    std::to_string(options.a_translation) + " and " + std::to_string(options.a_rotation));
    if (!std::isfinite(options.length_scale) || options.length_scale < 0)
        throw Error("DG-IDW: length_scale must be finite and >= 0 (0 = auto), got " +
                    std::to_string(options.length_scale));
    if (options.weighting != DgIdwWeighting::paper && options.weighting != DgIdwWeighting::continuous)
        throw Error("DG-IDW: unknown weighting " + std::to_string(static_cast<int>(options.weighting)));
}

DgIdwStepReport deform_dg_idw(const DgIdwPlan& plan, std::span<const double> points,
                              const BoundaryMotion& motion, std::span<double> out) {
    return deform_dg_idw_bounded(plan, points, motion, out, max_rotation_angle2(plan, motion));
}

double max_rotation_angle2(const DgIdwPlan& plan, const BoundaryMotion& motion) {
    double angle2_max = 0;
    for (std::size_t b = 0; b < motion.size() && b < plan.boundary_moving.size(); ++b) {
        if (!plan.boundary_moving[b]) continue;
        const Vec3& w = motion[b].rotation;
        angle2_max = std::max(angle2_max, plan.dim == 2 ? w[2] * w[2] : w[0] * w[0] + w[1] * w[1] + w[2] * w[2]);
    }
    return angle2_max;
}

DgIdwStepReport deform_dg_idw_bounded(const DgIdwPlan& plan, std::span<const double> points,
                                      const BoundaryMotion& motion, std::span<double> out, double angle2_max) {
    const DgIdwOptions& options = plan.options;
    check_dg_idw_options(options);
    check_step_arrays("DG-IDW", plan.num_points(), plan.dim, plan.boundary_nodes, points, motion, out);
    const double l = options.length_scale > 0 ? options.length_scale : plan.auto_length_scale;
    const StepConstants sc{1.0 / (options.a_translation * l), 1.0 / (options.a_rotation * l)};
    // The interpolated rotation vector is a combination of the moving nodes'
    // ones with non-negative weights summing to at most 1, so its angle is at
    // most their largest: that bounds the Taylor terms the step needs.
    const int terms = angle2_max == 0                           ? 0
                      : angle2_max <= taylor_angle2_limit(4) ? 4
                      : angle2_max <= taylor_angle2_limit(6) ? 6
                      : angle2_max <= taylor_angle2_limit(8) ? 8
                                                               : 10;

    auto run = [&]<int Dim, int Terms>() {
        // Blocks handed out as threads free up: the cost per node varies along
        // the node order (boundary nodes, simplices with 0 to 4 moving corners).
        parallel_for_blocks(plan.num_points(), deform_block, [&](std::int64_t begin, std::int64_t end) {
            deform_range<Dim, Terms>(plan, points.data(), motion.data(), out.data(), sc, begin, end);
        });
    };
    auto run_dim = [&]<int Dim>() {
        switch (terms) {
            case 0: return run.template operator()<Dim, 0>();
            case 4: return run.template operator()<Dim, 4>();
            case 6: return run.template operator()<Dim, 6>();
            case 8: return run.template operator()<Dim, 8>();
            default: return run.template operator()<Dim, 10>();
        }
    };
    if (plan.dim == 2) run_dim.template operator()<2>();
    else run_dim.template operator()<3>();
    return {count_conflicting_shared_vertices(plan.shared_offsets, plan.shared_members, plan.boundary_moving, motion)};
}

}  // namespace dgwarp
