#pragma once
// Internal to DG-harmonic (its step and its derivatives): a solve with one of
// its coarse factors (HarmonicFactors, L D Lᵀ in the factor's order).
#include <algorithm>
#include <cstdint>
#include <vector>

#include "dgwarp/methods/dg_harmonic.hpp"

namespace dgwarp::harmonic_detail {

/// y = (L D Lᵀ)⁻¹ y in place: n unknowns × C components, in the factor's
/// order, all components in one pass over L each way.
template <int C>
void solve_in_factor_order(const HarmonicFactors& f, const HarmonicFactors::System& sys, double* y) {
    const std::int64_t n = f.num_unknowns();
    const std::int64_t* start = f.l_start.data();
    const std::int32_t* row = f.l_row.data();
    const double* lv = sys.l_value.data();
    for (std::int64_t j = 0; j < n; ++j) {
        const double* yj = y + j * C;
        for (std::int64_t p = start[j]; p < start[j + 1]; ++p) {
            double* yi = y + static_cast<std::int64_t>(row[p]) * C;
            const double l = lv[p];
            for (int k = 0; k < C; ++k) yi[k] -= l * yj[k];
        }
    }
    for (std::int64_t j = 0; j < n; ++j) {
        const double inv = 1.0 / sys.d[j];
        for (int k = 0; k < C; ++k) y[j * C + k] *= inv;
    }
    for (std::int64_t j = n - 1; j >= 0; --j) {
        double* yj = y + j * C;
        double acc[C];
        for (int k = 0; k < C; ++k) acc[k] = yj[k];
        for (std::int64_t p = start[j]; p < start[j + 1]; ++p) {
            const double* yi = y + static_cast<std::int64_t>(row[p]) * C;
            const double l = lv[p];
            for (int k = 0; k < C; ++k) acc[k] -= l * yi[k];
        }
        for (int k = 0; k < C; ++k) yj[k] = acc[k];
    }
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
    solve_in_factor_order<C>(f, sys, y.data());
    for (std::int64_t i = 0; i < n; ++i)
        std::copy_n(y.data() + static_cast<std::size_t>(f.perm[i]) * C, C,
                    values + static_cast<std::size_t>(first_unknown + i) * K + Offset);
}

}  // namespace dgwarp::harmonic_detail
