#pragma once
// The two scalar factors of a rotation written as a displacement:
//   (R(w) - I) d = f (w × d) + g w × (w × d),  f = sin θ / θ,  g = (1 - cos θ) / θ²,
// θ = |w|. In 2D (w = (0, 0, φ)) this is (R - I) d = f φ (-d_y, d_x) - g φ² d.
// Used per node by interpolating methods, where std::sin and std::cos would
// dominate the step time.
#include <cmath>
#include <cstring>

namespace dgwarp {

struct RotationFactors {
    double f = 1.0;  // sin θ / θ
    double g = 0.5;  // (1 - cos θ) / θ²
};

namespace detail {
// Taylor coefficients, interleaved: taylor_pairs[2k] = (-1)^k / (2k+1)! (f),
// taylor_pairs[2k+1] = (-1)^k / (2k+2)! (g), k = 0..9.
struct TaylorPairs {
    double c[20];
};
constexpr TaylorPairs make_taylor_pairs() {
    TaylorPairs t{};
    double factorial = 1;  // n!, exact up to 18!, then within an ulp
    for (int n = 1; n <= 20; ++n) {
        factorial *= n;
        const int k = (n - 1) / 2;
        t.c[n - 1] = (k % 2 ? -1.0 : 1.0) / factorial;  // n odd: f's term k; n even: g's term k
    }
    return t;
}
inline constexpr TaylorPairs taylor_pairs = make_taylor_pairs();
// f and g evaluated side by side (two lanes of one SSE2 register).
using DoublePair = double __attribute__((vector_size(16)));
}  // namespace detail

/// The largest θ² for which `terms` Taylor terms (4, 6, 8 or 10) leave a
/// truncation error below 2^-56 in f and g: the first omitted term,
/// θ^(2 terms) / (2 terms + 1)!, is below 1.4e-17 there.
constexpr double taylor_angle2_limit(int terms) {
    return terms <= 4 ? 1.50e-3 : terms <= 6 ? 0.0664 : terms <= 8 ? 0.515 : 1.0;
}

/// f and g for θ² = angle2 <= taylor_angle2_limit(Terms), from Terms Taylor
/// terms (within a few ulp of the exact values). Estrin's scheme: pairs of
/// terms are combined independently, so the dependency chain is about half
/// as long as Horner's, which matters in per-node loops bound by latency.
template <int Terms>
inline RotationFactors rotation_factors_series(double angle2) {
    static_assert(Terms >= 2 && Terms <= 10 && Terms % 2 == 0);
    using detail::DoublePair;
    const double* c = detail::taylor_pairs.c;
    auto coefficient = [c](int k) {
        DoublePair v;
        std::memcpy(&v, c + 2 * k, sizeof v);
        return v;
    };
    const DoublePair x = {angle2, angle2};
    const DoublePair x2 = x * x;
    // Pair j: c_{2j} + c_{2j+1} x; then Horner in x² over the pairs.
    DoublePair acc = coefficient(Terms - 2) + coefficient(Terms - 1) * x;
    for (int j = Terms / 2 - 2; j >= 0; --j) acc = acc * x2 + (coefficient(2 * j) + coefficient(2 * j + 1) * x);
    return {acc[0], acc[1]};
}

/// f and g for any θ² = angle2 >= 0: 10 Taylor terms up to θ = 1 rad, beyond
/// that std::sin and std::cos.
inline RotationFactors rotation_factors(double angle2) {
    if (angle2 <= 1.0) return rotation_factors_series<10>(angle2);
    const double theta = std::sqrt(angle2);
    return {std::sin(theta) / theta, (1.0 - std::cos(theta)) / angle2};
}

}  // namespace dgwarp
