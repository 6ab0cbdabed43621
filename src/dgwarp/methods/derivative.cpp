// derivative.hpp: the products with J, DG-IDW's (DG-harmonic's are in
// dg_harmonic_derivative.cpp, beside its factor's solves), and the dispatch.
#include "dgwarp/methods/derivative.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "dgwarp/core/error.hpp"

namespace dgwarp {

namespace derivative_detail {

void check_arrays(const char* method, const char* product, int dim, std::size_t in_rows, std::size_t out_rows,
                  std::span<const double> in, std::span<const double> out) {
    const auto d = static_cast<std::size_t>(dim);
    const auto size_error = [&](const char* what, std::size_t rows, std::size_t given) {
        throw MeshError(std::string(method) + " " + product + ": " + what + " must hold " + std::to_string(rows) +
                        " × " + std::to_string(dim) + " values, got " + std::to_string(given));
    };
    if (in.size() != in_rows * d) size_error("the input", in_rows, in.size());
    if (out.size() != out_rows * d) size_error("the output", out_rows, out.size());
    for (std::size_t i = 0; i < in.size(); ++i)
        if (!std::isfinite(in[i]))
            throw MeshError(std::string(method) + " " + product + ": row " + std::to_string(i / d) +
                            " of the input is not finite");
}

}  // namespace derivative_detail

namespace {

/// DG-IDW's translation weights of volume node `i` (its simplex s, its
/// coefficients v): sigma_t and the number of moving corners, as the step
/// kernel computes them (dg_idw_step_kernel.inc); 0 moving corners when the
/// node does not move.
struct IdwNodeWeights {
    double sigma = 0;
    int moving = 0;
};

template <int Corners>
IdwNodeWeights idw_node_weights(const std::int32_t* corner, const double* v, double k_t) {
    IdwNodeWeights w;
    for (int k = 0; k < Corners; ++k) w.moving += corner[k] >= 0;  // moving corners come first
    double q_sum = 0, rho = 0;
    for (int k = 0; k < w.moving; ++k) q_sum += v[k];
    for (int k = w.moving; k < Corners; ++k) rho -= v[k];
    if (q_sum == 0) return {0, 0};  // on a static graph vertex
    w.sigma = 1.0 / (1.0 + rho * k_t);
    return w;
}

/// Calls node(i, b) for boundary node i of boundary index b, and
/// volume(i, corner, v, weights) for volume node i.
template <int Dim, class Boundary, class Volume>
void for_each_idw_node(const DgIdwPlan& plan, Boundary&& boundary, Volume&& volume) {
    constexpr int Corners = Dim + 1;
    const DgIdwOptions& o = plan.options;
    const double l = o.length_scale > 0 ? o.length_scale : plan.auto_length_scale;
    const double k_t = 1.0 / (o.a_translation * l);
    std::int64_t vol = 0;
    for (std::int64_t i = 0; i < plan.num_points(); ++i) {
        const std::int32_t s = plan.node_simplex[static_cast<std::size_t>(i)];
        if (s < 0) {
            boundary(i, -1 - s);
            continue;
        }
        const double* v = plan.node_coefficients.data() + vol * Corners;
        ++vol;
        const std::int32_t* corner = plan.simplex_motion.data() + static_cast<std::int64_t>(s) * Corners;
        volume(i, corner, v, idw_node_weights<Corners>(corner, v, k_t));
    }
}

template <int Dim>
void idw_forward(const DgIdwPlan& plan, const double* dir, double* out) {
    for_each_idw_node<Dim>(
        plan,
        [&](std::int64_t i, std::int32_t b) {
            for (int d = 0; d < Dim; ++d) out[i * Dim + d] = plan.boundary_moving[static_cast<std::size_t>(b)] ? dir[b * Dim + d] : 0.0;
        },
        [&](std::int64_t i, const std::int32_t* corner, const double* v, IdwNodeWeights w) {
            double t[Dim] = {};
            for (int k = 0; k < w.moving; ++k)
                for (int d = 0; d < Dim; ++d) t[d] += v[k] * dir[static_cast<std::int64_t>(corner[k]) * Dim + d];
            for (int d = 0; d < Dim; ++d) out[i * Dim + d] = w.sigma * t[d];
        });
}

template <int Dim>
void idw_transpose(const DgIdwPlan& plan, const double* weights, double* out) {
    for_each_idw_node<Dim>(
        plan,
        [&](std::int64_t i, std::int32_t b) {
            if (!plan.boundary_moving[static_cast<std::size_t>(b)]) return;
            for (int d = 0; d < Dim; ++d) out[b * Dim + d] += weights[i * Dim + d];
        },
        [&](std::int64_t i, const std::int32_t* corner, const double* v, IdwNodeWeights w) {
            for (int k = 0; k < w.moving; ++k) {
                const double c = w.sigma * v[k];
                for (int d = 0; d < Dim; ++d) out[static_cast<std::int64_t>(corner[k]) * Dim + d] += c * weights[i * Dim + d];
            }
        });
}

}  // namespace

void deform_derivative(const DgIdwPlan& plan, std::span<const double> direction, std::span<double> out) {
    derivative_detail::check_arrays("DG-IDW", "derivative", plan.dim, plan.boundary_nodes.size(),
                                    static_cast<std::size_t>(plan.num_points()), direction, out);
    if (plan.dim == 2) idw_forward<2>(plan, direction.data(), out.data());
    else idw_forward<3>(plan, direction.data(), out.data());
}

void deform_derivative_transpose(const DgIdwPlan& plan, std::span<const double> weights, std::span<double> out) {
    derivative_detail::check_arrays("DG-IDW", "derivative transpose", plan.dim,
                                    static_cast<std::size_t>(plan.num_points()), plan.boundary_nodes.size(), weights,
                                    out);
    std::fill(out.begin(), out.end(), 0.0);
    if (plan.dim == 2) idw_transpose<2>(plan, weights.data(), out.data());
    else idw_transpose<3>(plan, weights.data(), out.data());
}

bool has_deform_derivative(const Plan& plan) {
    return std::holds_alternative<DgIdwPlan>(plan) || std::holds_alternative<DgHarmonicPlan>(plan);
}

namespace {
[[noreturn]] void no_derivative(const Plan& plan) {
    throw Error(std::string(method_name(plan_method(plan))) +
                " has no derivative with respect to the boundary (dg-idw and dg-harmonic have)");
}
}  // namespace

void deform_derivative(const Plan& plan, std::span<const double> direction, std::span<double> out) {
    if (const auto* p = std::get_if<DgIdwPlan>(&plan)) return deform_derivative(*p, direction, out);
    if (const auto* p = std::get_if<DgHarmonicPlan>(&plan)) return deform_derivative(*p, direction, out);
    no_derivative(plan);
}

void deform_derivative_transpose(const Plan& plan, std::span<const double> weights, std::span<double> out) {
    if (const auto* p = std::get_if<DgIdwPlan>(&plan)) return deform_derivative_transpose(*p, weights, out);
    if (const auto* p = std::get_if<DgHarmonicPlan>(&plan)) return deform_derivative_transpose(*p, weights, out);
    no_derivative(plan);
}

}  // namespace dgwarp
