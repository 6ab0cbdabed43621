// Knupp's shape metric for triangles and tetrahedra (Knupp 2001): one corner
// Jacobian A (edges from node 0), α = det A, λ = AᵀA.
#include <cmath>

#include "dgwarp/quality/element_quality.hpp"

namespace dgwarp::quality_detail {

double triangle_alpha_2d(std::span<const Point3> x) {
    const Point3 a1 = minus(x[1], x[0]), a2 = minus(x[2], x[0]);
    return a1[0] * a2[1] - a1[1] * a2[0];
}

double triangle_quality(std::span<const Point3> x, bool planar, int orientation) {
    const Point3 a1 = minus(x[1], x[0]), a2 = minus(x[2], x[0]);
    const double alpha = planar ? orientation * triangle_alpha_2d(x) : std::sqrt(dot(cross(a1, a2), cross(a1, a2)));
    // λ11 + λ22 - λ12 = (sum of the three squared edge lengths) / 2 >= 0.
    const double denominator = dot(a1, a1) + dot(a2, a2) - dot(a1, a2);
    return corner_value({std::sqrt(3.0) * alpha, denominator});
}

double tetrahedron_alpha(std::span<const Point3> x) { return corner_jacobian(x[0], x[1], x[2], x[3]).alpha; }

double tetrahedron_quality(std::span<const Point3> x, int orientation) {
    const CornerJacobian j = corner_jacobian(x[0], x[1], x[2], x[3]);
    // 1.5 tr λ - (λ12 + λ23 + λ13) = (sum of the six squared edge lengths) / 2 >= 0.
    const double denominator = 1.5 * (j.l11 + j.l22 + j.l33) - (j.l12 + j.l23 + j.l13);
    return corner_value({3.0 * signed_two_thirds(std::sqrt(2.0) * orientation * j.alpha), denominator});
}

}  // namespace dgwarp::quality_detail
