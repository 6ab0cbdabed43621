// simplex_kernel.hpp: the simplices' shape metric, vectorised.
#include "dgwarp/quality/simplex_kernel.hpp"

#include <bit>
#include <cmath>
#include <cstdint>
#include <random>

#include "dgwarp/core/simd_clones.hpp"

namespace dgwarp::quality_detail {

namespace {

// glibc's sysdeps/ieee754/dbl-64/s_cbrt.c (the x86-64 libm's cbrt: frexp,
// this polynomial, one Newton step, a factor 2^(k/3) and ldexp), operation
// for operation; frexp and ldexp by the exponent's bits, exact for positive
// normal x (the result, about x^(1/3), is normal too).
inline double cbrt_of_normal(double x) {
    const auto bits = std::bit_cast<std::uint64_t>(x);
    const int e = static_cast<int>(bits >> 52) - 1022;  // x = xm 2^e, xm in [0.5, 1)
    const double xm = std::bit_cast<double>((bits & 0x000FFFFFFFFFFFFFull) | (std::uint64_t{1022} << 52));
    const double u =
        (0.354895765043919860 +
         ((1.50819193781584896 +
           ((-2.11499494167371287 +
             ((2.44693122563534430 + ((-1.83469277483613086 + (0.784932344976639262 - 0.145263899385486377 * xm) * xm) * xm)) *
              xm)) *
            xm)) *
          xm));
    const double t2 = u * u * u;
    const int r = e % 3;  // -2 .. 2, as C's % on a negative exponent
    const double factor = r == -2   ? 1.0 / 1.5874010519681994748
                          : r == -1 ? 1.0 / 1.2599210498948731648
                          : r == 0  ? 1.0
                          : r == 1  ? 1.2599210498948731648
                                    : 1.5874010519681994748;
    const double ym = u * (t2 + 2.0 * xm) / (2.0 * t2 + xm) * factor;
    return ym * std::bit_cast<double>(static_cast<std::uint64_t>(e / 3 + 1023) << 52);
}

bool normal_positive(double x) {
    return x >= 0x1p-1022 && x <= 0x1.fffffffffffffp1023;  // false for NaN
}

/// Whether cbrt_of_normal is this C library's cbrt: every exponent, and random mantissas.
bool same_as_library() {
    std::mt19937_64 rng(20261128);
    for (int e = -1022; e <= 1023; ++e)
        for (int k = 0; k < 8; ++k) {
            const double m = 1.0 + static_cast<double>(rng() >> 12) * 0x1p-52;
            const double x = std::ldexp(m, e);
            if (std::bit_cast<std::uint64_t>(cbrt_of_normal(x)) != std::bit_cast<std::uint64_t>(std::cbrt(x)))
                return false;
        }
    return true;
}

}  // namespace

double glibc_cbrt_of_normal(double x) { return cbrt_of_normal(x); }

DGWARP_SIMD_CLONES
void cube_roots_inline(const double* __restrict x, std::size_t count, double* __restrict root) {
    for (std::size_t i = 0; i < count; ++i) root[i] = cbrt_of_normal(x[i]);
}

void cube_roots(const double* x, std::size_t count, double* root) {
    static const bool same = same_as_library();
    if (!same) {
        for (std::size_t i = 0; i < count; ++i) root[i] = std::cbrt(x[i]);
        return;
    }
    cube_roots_inline(x, count, root);
    for (std::size_t i = 0; i < count; ++i)
        if (!normal_positive(x[i])) root[i] = std::cbrt(x[i]);
}

// No && in the loops (it keeps GCC from vectorising them): & on the comparisons.

namespace {

// Inlined into each clone below, so that each compiles the loops for its
// instruction set. GCC 12 then takes a[], filled for i < count, as maybe
// uninitialised where cube_roots reads it (for i < count too): a false alarm.
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#endif

/// tetrahedron_qualities, and with Alpha each α in `alpha`.
template <bool Alpha>
[[gnu::always_inline]] inline void tetrahedron_pass(const SimplexBlock& in, std::size_t count, double* __restrict quality,
                             double* __restrict alpha_out) {
    const double root2 = std::sqrt(2.0);
    double v[simplex_block], den[simplex_block], a[simplex_block], c[simplex_block];
    for (std::size_t i = 0; i < count; ++i) {
        // tetrahedron_quality: √2 × orientation × α.
        double alpha;
        tetrahedron_alpha_and_denominator(in, i, alpha, den[i]);
        if constexpr (Alpha) alpha_out[i] = alpha;
        v[i] = root2 * in.sign[i] * alpha;
        a[i] = std::fabs(v[i]);
    }
    cube_roots(a, count, c);
    for (std::size_t i = 0; i < count; ++i) {
        // signed_two_thirds, then corner_value (0 for a collapsed corner, no -0.0).
        const double t = v[i] < 0 ? -c[i] * c[i] : c[i] * c[i];
        const double q = 3.0 * t / den[i];
        quality[i] = (den[i] > 0) & (q != 0) ? q : 0.0;
    }
}

/// triangle_qualities, and with Alpha each α in `alpha`.
template <bool Alpha>
[[gnu::always_inline]] inline void triangle_pass(const SimplexBlock& in, std::size_t count, double* __restrict quality,
                          double* __restrict alpha_out) {
    const double root3 = std::sqrt(3.0);
    for (std::size_t i = 0; i < count; ++i) {
        // triangle_quality on a plane: α = orientation × (a1 × a2)_z (the z terms
        // of its 3D dots add +0, which changes no value here).
        double alpha, den;
        triangle_alpha_and_denominator(in, i, alpha, den);
        if constexpr (Alpha) alpha_out[i] = alpha;
        const double q = root3 * (in.sign[i] * alpha) / den;
        quality[i] = (den > 0) & (q != 0) ? q : 0.0;
    }
}

#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic pop
#endif

}  // namespace

DGWARP_SIMD_CLONES
void tetrahedron_qualities(const SimplexBlock& in, std::size_t count, double* __restrict quality) {
    tetrahedron_pass<false>(in, count, quality, nullptr);
}

DGWARP_SIMD_CLONES
void tetrahedron_qualities_and_alphas(const SimplexBlock& in, std::size_t count, double* __restrict quality,
                                      double* __restrict alpha) {
    tetrahedron_pass<true>(in, count, quality, alpha);
}

DGWARP_SIMD_CLONES
void triangle_qualities(const SimplexBlock& in, std::size_t count, double* __restrict quality) {
    triangle_pass<false>(in, count, quality, nullptr);
}

DGWARP_SIMD_CLONES
void triangle_qualities_and_alphas(const SimplexBlock& in, std::size_t count, double* __restrict quality,
                                   double* __restrict alpha) {
    triangle_pass<true>(in, count, quality, alpha);
}

DGWARP_SIMD_CLONES
void tetrahedron_alphas(const SimplexBlock& in, std::size_t count, double* __restrict alpha) {
    for (std::size_t i = 0; i < count; ++i) {
        double den;
        tetrahedron_alpha_and_denominator(in, i, alpha[i], den);
    }
}

DGWARP_SIMD_CLONES
void triangle_alphas(const SimplexBlock& in, std::size_t count, double* __restrict alpha) {
    for (std::size_t i = 0; i < count; ++i) {
        double den;
        triangle_alpha_and_denominator(in, i, alpha[i], den);
    }
}

}  // namespace dgwarp::quality_detail
