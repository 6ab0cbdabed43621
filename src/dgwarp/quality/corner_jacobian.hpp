#pragma once
// Internal to the quality module: the corner Jacobian shared by the element
// metrics and the rule that combines corner values into an element value.
// Formulas and their sources: docs/QUALITY.md.
#include <array>
#include <cmath>
#include <span>

namespace dgwarp::quality_detail {

using Point3 = std::array<double, 3>;

/// The nodes of one element as 3D points (z = 0 for 2D input). `coords`:
/// n × dim, row-major; `out` must hold n points.
inline void to_points(std::span<const double> coords, int dim, std::span<Point3> out) {
    for (std::size_t i = 0; i < out.size(); ++i)
        out[i] = {coords[i * dim], coords[i * dim + 1], dim == 3 ? coords[i * dim + 2] : 0.0};
}

/// to_points, then scaled by a power of two when the coordinates are so
/// large (beyond 2^400) that products of edge vectors would overflow to inf
/// and the metric to NaN: the metrics are scale invariant, and a power of
/// two keeps every bit of smaller meshes (they are not scaled).
inline void to_scaled_points(std::span<const double> coords, int dim, std::span<Point3> out) {
    to_points(coords, dim, out);
    double largest = 0;  // a NaN coordinate is passed over, as std::fmax would (inlined: no call per value)
    for (const Point3& p : out)
        for (double v : p) largest = std::fabs(v) > largest ? std::fabs(v) : largest;
    if (!(largest > 0x1p400) || !std::isfinite(largest)) return;
    const int e = std::ilogb(largest);
    for (Point3& p : out)
        for (double& v : p) v = std::ldexp(v, -e);
}

inline Point3 minus(const Point3& a, const Point3& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
inline double dot(const Point3& a, const Point3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
inline Point3 cross(const Point3& a, const Point3& b) {
    return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}

/// The Jacobian A = [a1 a2 a3] at a corner of a 3D element, its columns the
/// edge vectors from the corner: α = det A and the Gram matrix λ = AᵀA.
struct CornerJacobian {
    double alpha = 0;
    double l11 = 0, l22 = 0, l33 = 0;  // λ diagonal: squared edge lengths
    double l12 = 0, l13 = 0, l23 = 0;  // λ off-diagonal
};

/// The corner Jacobian at `corner` with edges to p1, p2, p3 (in that order).
inline CornerJacobian corner_jacobian(const Point3& corner, const Point3& p1, const Point3& p2,
                                      const Point3& p3) {
    const Point3 a1 = minus(p1, corner), a2 = minus(p2, corner), a3 = minus(p3, corner);
    return {dot(a3, cross(a1, a2)), dot(a1, a1), dot(a2, a2), dot(a3, a3),
            dot(a1, a2),            dot(a1, a3), dot(a2, a3)};
}

/// sign(v) |v|^(2/3): keeps the sign of a determinant through Knupp's 2/3 power.
inline double signed_two_thirds(double v) {
    const double c = std::cbrt(std::fabs(v));
    return v < 0 ? -c * c : c * c;
}

/// One corner's quality as a ratio: numerator (signed by the orientation; it
/// is <= 0 for an inverted corner) over a non-negative denominator, both
/// scaled so that the ideal corner has numerator == denominator.
struct CornerRatio {
    double numerator = 0;
    double denominator = 0;
};

/// The signed quality numerator / denominator of one corner, 0 when the
/// corner has collapsed to a point (denominator 0). Never NaN for finite input.
inline double corner_value(const CornerRatio& c) {
    if (!(c.denominator > 0)) return 0.0;
    const double q = c.numerator / c.denominator;
    return q == 0 ? 0.0 : q;  // no -0.0
}

/// Knupp's combination of corner qualities (harmonic mean, as in his
/// quadrilateral and hexahedron metrics): n / Σ_k denominator_k / numerator_k
/// when every corner is positive; otherwise the worst corner's signed value
/// (<= 0), so that an inverted element scores <= 0.
inline double combine_corners(std::span<const CornerRatio> corners) {
    double worst = corner_value(corners[0]);
    for (const CornerRatio& c : corners) {
        const double q = corner_value(c);
        if (q < worst) worst = q;
    }
    if (!(worst > 0)) return worst;
    double sum = 0;
    for (const CornerRatio& c : corners) sum += c.denominator / c.numerator;
    return static_cast<double>(corners.size()) / sum;  // sum = inf gives 0, never NaN
}

}  // namespace dgwarp::quality_detail
