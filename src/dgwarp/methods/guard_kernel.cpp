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
    const double largest = std::numeric_limits<double>::max(), nan = std::numeric_limits<double>::quiet_NaN();
    for (std::size_t i = 0; i < count; ++i) {
        double raw, den;
        quality_detail::tetrahedron_alpha_and_denominator(in, i, raw, den);
        const double a = in.sign[i] * raw;
        const double r = a / den;
        const double k = 54 * r * r / den;
        alpha[i] = a;
        key[i] = (a > 0) & (den > 0) & (k > 0) & (k <= largest) ? k : nan;
    }
}

DGWARP_SIMD_CLONES
void triangle_keys(const SimplexEdges& in, std::size_t count, double* __restrict alpha, double* __restrict key) {
    const double root3 = std::sqrt(3.0);
    const double largest = std::numeric_limits<double>::max(), nan = std::numeric_limits<double>::quiet_NaN();
    for (std::size_t i = 0; i < count; ++i) {
        double raw, den;
        quality_detail::triangle_alpha_and_denominator(in, i, raw, den);
        const double a = in.sign[i] * raw;
        const double k = root3 * a / den;
        alpha[i] = a;
        key[i] = (a > 0) & (den > 0) & (k > 0) & (k <= largest) ? k : nan;
    }
}

}  // namespace dgwarp::guard_detail
