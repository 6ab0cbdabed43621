// guard_kernel.hpp: the guard's measure arithmetic, vectorised.
#include "dgwarp/methods/guard_kernel.hpp"

#include <cmath>
#include <limits>

#include "dgwarp/core/simd_clones.hpp"

namespace dgwarp::guard_detail {

// No && and no std::isfinite in the loops: either keeps GCC from vectorising
// them. A key is kept when it is finite and positive; otherwise NaN sends the
// simplex to the exact path.

DGWARP_SIMD_CLONES
void tetrahedron_keys(const SimplexEdges& in, std::size_t count, double* __restrict alpha, double* __restrict key) {
    const double *a1x = in.e[0], *a1y = in.e[1], *a1z = in.e[2];
    const double *a2x = in.e[3], *a2y = in.e[4], *a2z = in.e[5];
    const double *a3x = in.e[6], *a3y = in.e[7], *a3z = in.e[8];
    const double largest = std::numeric_limits<double>::max(), nan = std::numeric_limits<double>::quiet_NaN();
    for (std::size_t i = 0; i < count; ++i) {
        // corner_jacobian: α = a3 · (a1 × a2), λ = AᵀA.
        const double c0 = a1y[i] * a2z[i] - a1z[i] * a2y[i];
        const double c1 = a1z[i] * a2x[i] - a1x[i] * a2z[i];
        const double c2 = a1x[i] * a2y[i] - a1y[i] * a2x[i];
        const double a = in.sign[i] * (a3x[i] * c0 + a3y[i] * c1 + a3z[i] * c2);
        const double l11 = a1x[i] * a1x[i] + a1y[i] * a1y[i] + a1z[i] * a1z[i];
        const double l22 = a2x[i] * a2x[i] + a2y[i] * a2y[i] + a2z[i] * a2z[i];
        const double l33 = a3x[i] * a3x[i] + a3y[i] * a3y[i] + a3z[i] * a3z[i];
        const double l12 = a1x[i] * a2x[i] + a1y[i] * a2y[i] + a1z[i] * a2z[i];
        const double l13 = a1x[i] * a3x[i] + a1y[i] * a3y[i] + a1z[i] * a3z[i];
        const double l23 = a2x[i] * a3x[i] + a2y[i] * a3y[i] + a2z[i] * a3z[i];
        const double den = 1.5 * (l11 + l22 + l33) - (l12 + l23 + l13);
        const double r = a / den;
        const double k = 54 * r * r / den;
        alpha[i] = a;
        key[i] = (a > 0) & (den > 0) & (k > 0) & (k <= largest) ? k : nan;
    }
}

DGWARP_SIMD_CLONES
void triangle_keys(const SimplexEdges& in, std::size_t count, double* __restrict alpha, double* __restrict key) {
    const double *a1x = in.e[0], *a1y = in.e[1], *a2x = in.e[2], *a2y = in.e[3];
    const double root3 = std::sqrt(3.0);
    const double largest = std::numeric_limits<double>::max(), nan = std::numeric_limits<double>::quiet_NaN();
    for (std::size_t i = 0; i < count; ++i) {
        const double a = in.sign[i] * (a1x[i] * a2y[i] - a1y[i] * a2x[i]);
        const double den = (a1x[i] * a1x[i] + a1y[i] * a1y[i]) + (a2x[i] * a2x[i] + a2y[i] * a2y[i]) -
                           (a1x[i] * a2x[i] + a1y[i] * a2y[i]);
        const double k = root3 * a / den;
        alpha[i] = a;
        key[i] = (a > 0) & (den > 0) & (k > 0) & (k <= largest) ? k : nan;
    }
}

}  // namespace dgwarp::guard_detail
