// derivative.hpp for DG-harmonic: the products with J of its one pass for
// translations (dg_harmonic_deform.cpp's step without rotation): the boundary
// vertices' translations, the interior vertices' from one solve with the
// translation factor, then each volume node the barycentric combination of
// its coarse simplex's corners.
#include <algorithm>
#include <vector>

#include "dgwarp/methods/derivative.hpp"
#include "dgwarp/methods/dg_harmonic_solve.hpp"

namespace dgwarp {

namespace {

template <int Dim>
void harmonic_forward(const DgHarmonicPlan& plan, const double* dir, double* out) {
    constexpr int Corners = Dim + 1;
    std::vector<double> values(static_cast<std::size_t>(plan.num_vertices()) * Dim, 0.0);
    for (std::int32_t v = 0; v < plan.num_boundary_vertices; ++v) {
        const std::int32_t b = plan.vertex_motion[static_cast<std::size_t>(v)];
        if (b >= 0) std::copy_n(dir + static_cast<std::size_t>(b) * Dim, Dim, values.data() + static_cast<std::size_t>(v) * Dim);
    }
    harmonic_detail::solve_interior<Dim, 0, Dim>(plan.solve, plan.solve.translation, plan.num_boundary_vertices,
                                                 values.data());
    std::int64_t vol = 0;
    for (std::int64_t i = 0; i < plan.num_points(); ++i) {
        double* y = out + i * Dim;
        const std::int32_t s = plan.node_simplex[static_cast<std::size_t>(i)];
        if (s < 0) {
            const std::int32_t b = -1 - s;
            for (int d = 0; d < Dim; ++d) y[d] = plan.boundary_moving[static_cast<std::size_t>(b)] ? dir[b * Dim + d] : 0.0;
            continue;
        }
        const double* e = plan.node_barycentric.data() + vol * Corners;
        ++vol;
        const std::int32_t* c = plan.simplices.data() + static_cast<std::int64_t>(s) * Corners;
        double t[Dim] = {};
        for (int k = 0; k < Corners; ++k)
            for (int d = 0; d < Dim; ++d) t[d] += e[k] * values[static_cast<std::size_t>(c[k]) * Dim + d];
        for (int d = 0; d < Dim; ++d) y[d] = t[d];
    }
}

template <int Dim>
void harmonic_transpose(const DgHarmonicPlan& plan, const double* weights, double* out) {
    constexpr int Corners = Dim + 1;
    const HarmonicFactors& f = plan.solve;
    // The adjoint of each coarse vertex's translation, from the nodes.
    std::vector<double> a(static_cast<std::size_t>(plan.num_vertices()) * Dim, 0.0);
    std::int64_t vol = 0;
    for (std::int64_t i = 0; i < plan.num_points(); ++i) {
        const double* w = weights + i * Dim;
        const std::int32_t s = plan.node_simplex[static_cast<std::size_t>(i)];
        if (s < 0) {
            const std::int32_t b = -1 - s;
            if (plan.boundary_moving[static_cast<std::size_t>(b)])
                for (int d = 0; d < Dim; ++d) out[b * Dim + d] += w[d];
            continue;
        }
        const double* e = plan.node_barycentric.data() + vol * Corners;
        ++vol;
        const std::int32_t* c = plan.simplices.data() + static_cast<std::int64_t>(s) * Corners;
        for (int k = 0; k < Corners; ++k)
            for (int d = 0; d < Dim; ++d) a[static_cast<std::size_t>(c[k]) * Dim + d] += e[k] * w[d];
    }
    // The interior vertices' values are P (L D Lᵀ)⁻¹ Pᵀ B g: their adjoint
    // goes back through the same factor (the Laplacian is symmetric) and the
    // coupling B to the boundary vertices.
    const std::int64_t n = f.num_unknowns();
    const std::int32_t nb = plan.num_boundary_vertices;
    if (n > 0) {
        std::vector<double> z(static_cast<std::size_t>(n) * Dim);
        for (std::int64_t i = 0; i < n; ++i)
            std::copy_n(a.data() + static_cast<std::size_t>(nb + i) * Dim, Dim,
                        z.data() + static_cast<std::size_t>(f.perm[static_cast<std::size_t>(i)]) * Dim);
        harmonic_detail::solve_in_factor_order<Dim>(f, f.translation, z.data());
        for (std::int64_t i = 0; i < n; ++i) {
            const double* zi = z.data() + static_cast<std::size_t>(f.perm[static_cast<std::size_t>(i)]) * Dim;
            for (std::int64_t p = f.coupling_start[static_cast<std::size_t>(i)]; p < f.coupling_start[static_cast<std::size_t>(i) + 1]; ++p) {
                const auto v = static_cast<std::size_t>(f.coupling_vertex[static_cast<std::size_t>(p)]);
                if (v >= static_cast<std::size_t>(nb)) continue;  // an interior vertex's value is not data
                const double cw = f.translation.coupling_weight[static_cast<std::size_t>(p)];
                for (int d = 0; d < Dim; ++d) a[v * Dim + d] += cw * zi[d];
            }
        }
    }
    // The boundary vertices carry their boundary node's translation.
    for (std::int32_t v = 0; v < nb; ++v) {
        const std::int32_t b = plan.vertex_motion[static_cast<std::size_t>(v)];
        if (b < 0) continue;
        for (int d = 0; d < Dim; ++d) out[b * Dim + d] += a[static_cast<std::size_t>(v) * Dim + d];
    }
}

}  // namespace

void deform_derivative(const DgHarmonicPlan& plan, std::span<const double> direction, std::span<double> out) {
    derivative_detail::check_arrays("DG-harmonic", "derivative", plan.dim, plan.boundary_nodes.size(),
                                    static_cast<std::size_t>(plan.num_points()), direction, out);
    if (plan.dim == 2) harmonic_forward<2>(plan, direction.data(), out.data());
    else harmonic_forward<3>(plan, direction.data(), out.data());
}

void deform_derivative_transpose(const DgHarmonicPlan& plan, std::span<const double> weights,
                                 std::span<double> out) {
    derivative_detail::check_arrays("DG-harmonic", "derivative transpose", plan.dim,
                                    static_cast<std::size_t>(plan.num_points()), plan.boundary_nodes.size(), weights,
                                    out);
    std::fill(out.begin(), out.end(), 0.0);
    if (plan.dim == 2) harmonic_transpose<2>(plan, weights.data(), out.data());
    else harmonic_transpose<3>(plan, weights.data(), out.data());
}

}  // namespace dgwarp
