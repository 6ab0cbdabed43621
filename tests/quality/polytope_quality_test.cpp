// Polygons and polyhedra (quality/polytope_quality.cpp): their pieces from
// centres against the regular polygon's, checked on shapes whose values are
// known by hand: regular polygons and cubes score 1, a polygon given as
// triangle or quadrilateral the same as that cell when regular, an inverted
// one <= 0, and the measure invariant under moves and scaling.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <numbers>
#include <vector>

#include "dgwarp/quality/cell_quality.hpp"

using namespace dgwarp;

namespace {

/// A regular n-gon of circumradius r about (cx, cy), counter-clockwise.
ElementList regular_polygon(int n, double r, double cx, double cy, std::vector<double>& points) {
    ElementList list;
    std::vector<NodeId> nodes;
    for (int k = 0; k < n; ++k) {
        const double a = 2 * std::numbers::pi * k / n + 0.3;
        nodes.push_back(static_cast<NodeId>(points.size() / 2));
        points.push_back(cx + r * std::cos(a));
        points.push_back(cy + r * std::sin(a));
    }
    list.push_back(CellType::polygon, nodes);
    return list;
}

/// The unit cube [0,1]^3 as a polyhedron with its 6 faces pointing out.
ElementList cube_polyhedron() {
    ElementList list;
    const std::vector<NodeId> rings{0, 3, 2, 1, 4, 5, 6, 7, 0, 1, 5, 4, 1, 2, 6, 5, 2, 3, 7, 6, 3, 0, 4, 7};
    const std::vector<int> sizes(6, 4);
    list.push_polyhedron(rings, sizes);
    return list;
}

std::vector<double> cube_points() {
    return {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0, 0, 0, 1, 1, 0, 1, 1, 1, 1, 0, 1, 1};
}

}  // namespace

TEST(PolytopeQuality, RegularPolygonsScoreOneAndSquaresAsQuadrilaterals) {
    for (int n = 3; n <= 12; ++n) {
        std::vector<double> points;
        const ElementList p = regular_polygon(n, 2.5, 1.0, -3.0, points);
        EXPECT_NEAR(element_shape_quality(p, 0, 2, points), 1.0, 1e-12) << n << " sides";
        EXPECT_EQ(element_orientation(p, 0, 2, points), 1);
    }
    // A unit square as a polygon: 1, as the quadrilateral; a 2 × 1 rectangle:
    // each piece's shape against the square's piece.
    const std::vector<double> rectangle{0, 0, 2, 0, 2, 1, 0, 1};
    ElementList list;
    list.push_back(CellType::polygon, std::array<NodeId, 4>{0, 1, 2, 3});
    const double got = element_shape_quality(list, 0, 2, rectangle);
    // Each of its four pieces from the centre (1, 0.5): legs of length √1.25,
    // α = 1 (twice the area 0.5). The square's piece W has legs 1/√2 at 90°:
    // det W = 1/2, (WᵀW)⁻¹ = 2 I. So det T = α / det W = 2 and |T|_F² =
    // 2 (λ11 + λ22) = 2 × 2.5 = 5: Knupp's 2 det T / |T|² = 0.8, for every piece.
    EXPECT_NEAR(got, 0.8, 1e-12);
}

TEST(PolytopeQuality, ACubeAsAPolyhedronScoresOneInAnyPlaceAndSize) {
    const ElementList cube = cube_polyhedron();
    std::vector<double> p = cube_points();
    EXPECT_NEAR(element_shape_quality(cube, 0, 3, p), 1.0, 1e-12);
    EXPECT_EQ(element_orientation(cube, 0, 3, p), 1);
    // Turned about z by 30°, scaled by 1e-3 and moved: the same.
    const double c = std::cos(0.5235987755982988), s = std::sin(0.5235987755982988);
    std::vector<double> q(p.size());
    for (std::size_t i = 0; i < p.size(); i += 3) {
        q[i] = 1e-3 * (c * p[i] - s * p[i + 1]) + 7;
        q[i + 1] = 1e-3 * (s * p[i] + c * p[i + 1]) - 2;
        q[i + 2] = 1e-3 * p[i + 2] + 0.5;
    }
    EXPECT_NEAR(element_shape_quality(cube, 0, 3, q), 1.0, 1e-10);
    // A box of 2 × 1 × 1 scores below 1, above 0.
    for (std::size_t i = 0; i < p.size(); i += 3) p[i] *= 2;
    const double box = element_shape_quality(cube, 0, 3, p);
    EXPECT_GT(box, 0.5);
    EXPECT_LT(box, 0.99);
}

TEST(PolytopeQuality, MirroredFacesAreTheOtherOrientationAndAFoldIsInverted) {
    // The cube with every face turned inward: orientation -1; judged against
    // -1 it is the ideal cube again.
    ElementList inward;
    const std::vector<NodeId> rings{0, 1, 2, 3, 4, 7, 6, 5, 0, 4, 5, 1, 1, 5, 6, 2, 2, 6, 7, 3, 3, 7, 4, 0};
    inward.push_polyhedron(rings, std::vector<int>(6, 4));
    std::vector<double> p = cube_points();
    EXPECT_EQ(element_orientation(inward, 0, 3, p), -1);
    EXPECT_NEAR(element_shape_quality(inward, 0, 3, p, -1), 1.0, 1e-12);
    EXPECT_LT(element_shape_quality(inward, 0, 3, p, 1), 0.0);
    // Node 6 pushed through the bottom face: some pieces turn over.
    const ElementList cube = cube_polyhedron();
    p[6 * 3 + 2] = -0.5;
    p[6 * 3 + 0] = p[6 * 3 + 1] = 0.5;
    EXPECT_LE(element_shape_quality(cube, 0, 3, p), 0.0);
    // A polygon written clockwise in 2D: orientation -1.
    std::vector<double> square{0, 0, 0, 1, 1, 1, 1, 0};
    ElementList cw;
    cw.push_back(CellType::polygon, std::array<NodeId, 4>{0, 1, 2, 3});
    EXPECT_EQ(element_orientation(cw, 0, 2, square), -1);
    EXPECT_NEAR(element_shape_quality(cw, 0, 2, square, -1), 1.0, 1e-12);
}

TEST(PolytopeQuality, FixedTypesThroughTheListAreCellShapeQualityToTheBit) {
    // element_shape_quality of a hexahedron or a tetrahedron is cell_shape_quality's.
    const std::vector<double> p{0, 0, 0, 1.1, 0, 0, 1, 0.9, 0.1, 0, 1, 0, 0, 0, 1, 1, 0, 1.2, 1, 1, 1, 0.1, 1, 1};
    ElementList list;
    list.push_back(CellType::hexahedron, std::array<NodeId, 8>{0, 1, 2, 3, 4, 5, 6, 7});
    list.push_back(CellType::tetrahedron, std::array<NodeId, 4>{0, 1, 3, 4});
    EXPECT_EQ(element_shape_quality(list, 0, 3, p), cell_shape_quality(CellType::hexahedron, p, 3));
    const std::vector<double> tet{0, 0, 0, 1.1, 0, 0, 0, 1, 0, 0, 0, 1};
    EXPECT_EQ(element_shape_quality(list, 1, 3, p), cell_shape_quality(CellType::tetrahedron, tet, 3));
    EXPECT_EQ(element_orientation(list, 0, 3, p), cell_orientation(CellType::hexahedron, p, 3));
}
