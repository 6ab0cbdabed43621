// Corner-based shape metrics: Knupp's quadrilateral and hexahedron (Knupp
// 2001) and their extension to prisms and pyramids (docs/QUALITY.md). Each
// corner's edges are taken in the order that gives a correctly oriented VTK
// element positive determinants.
#include <array>
#include <cmath>

#include "dgwarp/quality/element_quality.hpp"

namespace dgwarp::quality_detail {

namespace {

// ---- corner tables (VTK node order) -------------------------------------

// Hexahedron: bottom corner k: (next, previous, above); top corner: (previous, next, below),
// "next" counter-clockwise seen from the top face.
constexpr int hex_corners[8][4] = {{0, 1, 3, 4}, {1, 2, 0, 5}, {2, 3, 1, 6}, {3, 0, 2, 7},
                                   {4, 7, 5, 0}, {5, 4, 6, 1}, {6, 5, 7, 2}, {7, 6, 4, 3}};

// VTK wedge: (0,1,2)'s right-hand normal points away from (3,4,5), so seen from
// the top the counter-clockwise order is 0,2,1 (and 3,5,4).
constexpr int prism_corners[6][4] = {{0, 2, 1, 3}, {1, 0, 2, 4}, {2, 1, 0, 5},
                                     {3, 4, 5, 0}, {4, 5, 3, 1}, {5, 3, 4, 2}};

// VTK pyramid: base (0,1,2,3) counter-clockwise seen from the apex 4. Base
// corner k: (next, previous, apex). The apex has 4 edges; it is split into 4
// tetrahedral sub-corners, sub-corner m leaving out the edge to base node m+2:
// (apex→m-1, apex→m+1, apex→m).
constexpr int pyramid_corners[8][4] = {{0, 1, 3, 4}, {1, 2, 0, 4}, {2, 3, 1, 4}, {3, 0, 2, 4},
                                       {4, 3, 1, 0}, {4, 0, 2, 1}, {4, 1, 3, 2}, {4, 2, 0, 3}};

template <std::size_t N>
std::array<CornerJacobian, N> corner_jacobians(std::span<const Point3> x, const int (&table)[N][4]) {
    std::array<CornerJacobian, N> j;
    for (std::size_t k = 0; k < N; ++k)
        j[k] = corner_jacobian(x[table[k][0]], x[table[k][1]], x[table[k][2]], x[table[k][3]]);
    return j;
}

template <std::size_t N>
double alpha_sum(const std::array<CornerJacobian, N>& corners) {
    double s = 0;
    for (const CornerJacobian& c : corners) s += c.alpha;
    return s;
}

// Corner shape 3 det(T)^(2/3) / |T|_F² with T = A W⁻¹, W the ideal corner;
// `det_scale` = 1 / det W and `denominator` = tr(λ (WᵀW)⁻¹).
CornerRatio solid_corner(double alpha, int orientation, double det_scale, double denominator) {
    return {3.0 * signed_two_thirds(det_scale * orientation * alpha), denominator};
}

// Quadrilateral corner k: edges to the next and the previous node.
void quadrilateral_edges(std::span<const Point3> x, int k, Point3& e1, Point3& e2) {
    e1 = minus(x[(k + 1) % 4], x[k]);
    e2 = minus(x[(k + 3) % 4], x[k]);
}

}  // namespace

double quadrilateral_alpha_sum_2d(std::span<const Point3> x) {
    double s = 0;
    for (int k = 0; k < 4; ++k) {
        Point3 e1, e2;
        quadrilateral_edges(x, k, e1, e2);
        s += e1[0] * e2[1] - e1[1] * e2[0];
    }
    return s;
}

double quadrilateral_quality(std::span<const Point3> x, bool planar, int orientation) {
    std::array<Point3, 4> e1, e2, normals;
    Point3 mean_normal{0, 0, 0};
    for (int k = 0; k < 4; ++k) {
        quadrilateral_edges(x, k, e1[k], e2[k]);
        normals[k] = cross(e1[k], e2[k]);
        for (int c = 0; c < 3; ++c) mean_normal[c] += normals[k][c];
    }
    // In 3D space a quadrilateral has no orientation of its own: measure each
    // corner's α along the mean normal, so a folded or non-convex corner is
    // still negative. A zero mean normal (collapsed quad) gives α = 0.
    const double normal_length = std::sqrt(dot(mean_normal, mean_normal));
    std::array<CornerRatio, 4> corners;
    for (int k = 0; k < 4; ++k) {
        double alpha = 0;
        if (planar)
            alpha = orientation * normals[k][2];
        else if (normal_length > 0)
            alpha = dot(normals[k], mean_normal) / normal_length;
        // Knupp: corner value (λ11 + λ22) / α, ideal 2.
        corners[k] = {2.0 * alpha, dot(e1[k], e1[k]) + dot(e2[k], e2[k])};
    }
    return combine_corners(corners);
}

double hexahedron_alpha_sum(std::span<const Point3> x) { return alpha_sum(corner_jacobians(x, hex_corners)); }
double prism_alpha_sum(std::span<const Point3> x) { return alpha_sum(corner_jacobians(x, prism_corners)); }
double pyramid_alpha_sum(std::span<const Point3> x) { return alpha_sum(corner_jacobians(x, pyramid_corners)); }

double hexahedron_quality(std::span<const Point3> x, int orientation) {
    // Knupp: corner value tr λ / α^(2/3), ideal 3 (W = I).
    const auto j = corner_jacobians(x, hex_corners);
    std::array<CornerRatio, 8> corners;
    for (std::size_t k = 0; k < j.size(); ++k)
        corners[k] = solid_corner(j[k].alpha, orientation, 1.0, j[k].l11 + j[k].l22 + j[k].l33);
    return combine_corners(corners);
}

double prism_quality(std::span<const Point3> x, int orientation) {
    // Ideal corner: two unit edges at 60° (the equilateral base) and a unit
    // edge normal to them; det W = √3/2, (WᵀW)⁻¹ = [[4/3, -2/3, 0], [-2/3, 4/3, 0], [0, 0, 1]].
    const auto j = corner_jacobians(x, prism_corners);
    std::array<CornerRatio, 6> corners;
    for (std::size_t k = 0; k < j.size(); ++k) {
        const CornerJacobian& c = j[k];
        corners[k] = solid_corner(c.alpha, orientation, 2.0 / std::sqrt(3.0),
                                  (4.0 / 3.0) * (c.l11 + c.l22 - c.l12) + c.l33);
    }
    return combine_corners(corners);
}

double pyramid_quality(std::span<const Point3> x, int orientation) {
    // Ideal corner (base corners and apex sub-corners alike): two orthogonal
    // unit edges and a unit edge at 60° to both; det W = 1/√2,
    // (WᵀW)⁻¹ = [[3/2, 1/2, -1], [1/2, 3/2, -1], [-1, -1, 2]].
    const auto j = corner_jacobians(x, pyramid_corners);
    std::array<CornerRatio, 8> corners;
    for (std::size_t k = 0; k < j.size(); ++k) {
        const CornerJacobian& c = j[k];
        corners[k] = solid_corner(c.alpha, orientation, std::sqrt(2.0),
                                  1.5 * (c.l11 + c.l22) + c.l12 + 2.0 * c.l33 - 2.0 * (c.l13 + c.l23));
    }
    return combine_corners(corners);
}

}  // namespace dgwarp::quality_detail
