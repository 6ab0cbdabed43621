// deform_dg_idw: one pass over the nodes per step.
#include <algorithm>
#include <cmath>
#include <string>

#include "dgwarp/core/error.hpp"
#include "dgwarp/core/parallel_for.hpp"
#include "dgwarp/methods/dg_idw.hpp"
#include "dgwarp/methods/dg_idw_checks.hpp"
#include "dgwarp/methods/graph_vertex_motion.hpp"
#include "dgwarp/methods/rotation_series.hpp"

namespace dgwarp {

namespace {

// Per-step constants of the weights (dg_idw.hpp): A = a L^2 for each a, L for static corners.
struct StepConstants {
    double a_t;  // a_translation L^2
    double a_r;  // a_rotation L^2
    double l;    // L
};

bool is_zero(const Vec3& v) { return v[0] == 0 && v[1] == 0 && v[2] == 0; }

// Moves nodes [begin, end): boundary nodes by their own motion, volume nodes
// by the interpolated one. Rotate = false when no moving boundary node rotates.
template <int Dim, bool Rotate>
void deform_range(const DgIdwPlan& plan, const double* x0, const NodeMotion* motion, double* out,
                  const StepConstants& sc, std::int64_t begin, std::int64_t end) {
    constexpr int Corners = Dim + 1;
    // Volume index of the first volume node at or after `begin`.
    std::int64_t vol = begin - (std::lower_bound(plan.boundary_nodes.begin(), plan.boundary_nodes.end(), begin) -
                                plan.boundary_nodes.begin());
    const std::int32_t* node_simplex = plan.node_simplex.data();
    const std::int32_t* simplices = plan.simplices.data();
    const std::int32_t* vertex_motion = plan.vertex_motion.data();
    const double* coefficients = plan.node_coefficients.data();
    for (std::int64_t i = begin; i < end; ++i) {
        const double* x = x0 + i * Dim;
        double* y = out + i * Dim;
        const std::int32_t s = node_simplex[i];
        if (s < 0) {
            const std::int32_t b = -1 - s;
            if (plan.boundary_moving[b]) {
                apply_motion(motion[b], std::span<const double>(x, Dim), std::span<double>(y, Dim));
            } else {
                for (int d = 0; d < Dim; ++d) y[d] = x[d];
            }
            continue;
        }
        const double* q = coefficients + vol * Corners;
        ++vol;
        const std::int32_t* corner = simplices + static_cast<std::int64_t>(s) * Corners;
        std::int32_t m[Corners];
        double den_t = 0, den_r = 0, q_moving = 0;
        for (int k = 0; k < Corners; ++k) {
            m[k] = vertex_motion[corner[k]];
            const bool moving = m[k] >= 0;
            den_t += (moving ? sc.a_t : sc.l) * q[k];
            if constexpr (Rotate) den_r += (moving ? sc.a_r : sc.l) * q[k];
            q_moving += moving ? q[k] : 0.0;
        }
        if (q_moving == 0) {  // no moving corner, or on a static vertex
            for (int d = 0; d < Dim; ++d) y[d] = x[d];
            continue;
        }
        const double scale_t = sc.a_t / den_t;
        double t[Dim] = {};
        for (int k = 0; k < Corners; ++k) {
            if (m[k] < 0) continue;
            const double w = scale_t * q[k];
            for (int d = 0; d < Dim; ++d) t[d] += w * motion[m[k]].translation[d];
        }
        if constexpr (!Rotate) {
            for (int d = 0; d < Dim; ++d) y[d] = x[d] + t[d];
        } else {
            const double scale_r = sc.a_r / den_r;
            constexpr int W = Dim == 2 ? 1 : 3;  // rotation components: w_z in 2D
            double w[W] = {}, c[Dim] = {};
            for (int k = 0; k < Corners; ++k) {
                if (m[k] < 0) continue;
                const NodeMotion& mk = motion[m[k]];
                const double wr = scale_r * q[k];
                for (int j = 0; j < W; ++j) w[j] += wr * mk.rotation[3 - W + j];
                for (int d = 0; d < Dim; ++d) c[d] += q[k] * mk.center[d];
            }
            const double inv_q = 1.0 / q_moving;
            double e[Dim];  // x0 - c
            for (int d = 0; d < Dim; ++d) e[d] = x[d] - c[d] * inv_q;
            if constexpr (Dim == 2) {
                const RotationFactors r = rotation_factors(w[0] * w[0]);
                const double fw = r.f * w[0], gw2 = r.g * w[0] * w[0];
                y[0] = x[0] + (t[0] + (-fw * e[1] - gw2 * e[0]));
                y[1] = x[1] + (t[1] + (fw * e[0] - gw2 * e[1]));
            } else {
                const RotationFactors r = rotation_factors(w[0] * w[0] + w[1] * w[1] + w[2] * w[2]);
                const double we[3] = {w[1] * e[2] - w[2] * e[1], w[2] * e[0] - w[0] * e[2], w[0] * e[1] - w[1] * e[0]};
                const double wwe[3] = {w[1] * we[2] - w[2] * we[1], w[2] * we[0] - w[0] * we[2],
                                       w[0] * we[1] - w[1] * we[0]};
                for (int d = 0; d < 3; ++d) y[d] = x[d] + (t[d] + (r.f * we[d] + r.g * wwe[d]));
            }
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
}

DgIdwStepReport deform_dg_idw(const DgIdwPlan& plan, std::span<const double> points,
                              const BoundaryMotion& motion, std::span<double> out, const DgIdwOptions& options) {
    check_dg_idw_options(options);
    const auto expected = static_cast<std::size_t>(plan.num_points()) * static_cast<std::size_t>(plan.dim);
    if (points.size() != expected)
        throw MeshError("DG-IDW: the plan is for " + std::to_string(plan.num_points()) + " points (" +
                        std::to_string(expected) + " coordinates), got " + std::to_string(points.size()) +
                        " coordinates");
    if (out.size() != expected)
        throw MeshError("DG-IDW: the output array holds " + std::to_string(out.size()) + " values, expected " +
                        std::to_string(expected) + " (" + std::to_string(plan.num_points()) + " points)");
    if (motion.size() != plan.boundary_nodes.size())
        throw MeshError("DG-IDW: the motion has " + std::to_string(motion.size()) + " entries but the plan has " +
                        std::to_string(plan.boundary_nodes.size()) + " boundary nodes");

    const double l = options.length_scale > 0 ? options.length_scale : plan.auto_length_scale;
    const StepConstants sc{options.a_translation * l * l, options.a_rotation * l * l, l};
    bool rotate = false;
    for (std::size_t b = 0; b < motion.size() && !rotate; ++b)
        rotate = plan.boundary_moving[b] && !is_zero(motion[b].rotation);
    // In 2D only w_z rotates.
    if (rotate && plan.dim == 2) {
        rotate = false;
        for (std::size_t b = 0; b < motion.size() && !rotate; ++b)
            rotate = plan.boundary_moving[b] && motion[b].rotation[2] != 0;
    }

    auto run = [&](auto kernel) {
        parallel_for_chunks(plan.num_points(), [&](std::int64_t begin, std::int64_t end) {
            kernel(plan, points.data(), motion.data(), out.data(), sc, begin, end);
        });
    };
    if (plan.dim == 2) {
        if (rotate) run(deform_range<2, true>);
        else run(deform_range<2, false>);
    } else {
        if (rotate) run(deform_range<3, true>);
        else run(deform_range<3, false>);
    }
    return {count_conflicting_shared_vertices(plan.shared_offsets, plan.shared_members, plan.boundary_moving, motion)};
}

}  // namespace dgwarp
