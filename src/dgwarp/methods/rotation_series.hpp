#pragma once
// The two scalar factors of a rotation written as a displacement:
//   (R(w) - I) d = f (w × d) + g w × (w × d),  f = sin θ / θ,  g = (1 - cos θ) / θ²,
// θ = |w|. In 2D (w = (0, 0, φ)) this is (R - I) d = f φ (-d_y, d_x) - g φ² d.
// Used per node by interpolating methods, where std::sin and std::cos would
// dominate the step time.
#include <cmath>

namespace dgwarp {

struct RotationFactors {
    double f = 1.0;  // sin θ / θ
    double g = 0.5;  // (1 - cos θ) / θ²
};

namespace detail {
// Taylor coefficients (-1)^k / (2k+1)! and (-1)^k / (2k+2)!, k = 0..9.
struct TaylorTables {
    double f[10];
    double g[10];
};
constexpr TaylorTables make_taylor_tables() {
    TaylorTables t{};
    double factorial = 1;  // n!
    for (int n = 1; n <= 20; ++n) {
        factorial *= n;  // exact up to 18!, then within an ulp
        const int k = (n - 1) / 2;
        const double sign = k % 2 ? -1.0 : 1.0;
        if (n % 2 == 1) t.f[k] = sign / factorial;
        else t.g[(n - 2) / 2] = sign / factorial;
    }
    return t;
}
inline constexpr TaylorTables taylor = make_taylor_tables();
}  // namespace detail

/// f and g for θ² = angle2 (>= 0). For θ <= 1 rad: Taylor series to degree 9
/// in θ² (truncation below 2e-20, so within a few ulp of the exact values);
/// beyond, std::sin and std::cos.
inline RotationFactors rotation_factors(double angle2) {
    if (angle2 <= 1.0) {
        const auto& c = detail::taylor;
        double f = c.f[9], g = c.g[9];
        for (int k = 8; k >= 0; --k) {
            f = f * angle2 + c.f[k];
            g = g * angle2 + c.g[k];
        }
        return {f, g};
    }
    const double theta = std::sqrt(angle2);
    return {std::sin(theta) / theta, (1.0 - std::cos(theta)) / angle2};
}

}  // namespace dgwarp
