#include "dgwarp/quality/cell_quality.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "quality/quality_test_elements.hpp"

using namespace dgwarp;
using dgwarp::test::ideal_element;
using dgwarp::test::quality_types;
using dgwarp::test::TestElement;

namespace {

double q(CellType type, std::vector<double> x, int dim = 2) { return cell_shape_quality(type, x, dim); }

}  // namespace

// ---- METHODS.md reference values ----------------------------------------

TEST(QualityReference, Triangles) {
    const double s3 = std::sqrt(3.0);
    EXPECT_NEAR(q(CellType::triangle, {0, 0, 1, 0, 0.5, s3 / 2}), 1.0, 1e-12);
    EXPECT_NEAR(q(CellType::triangle, {0, 0, 1, 0, 0, 1}), s3 / 2, 1e-12);
    EXPECT_NEAR(q(CellType::triangle, {0, 0, s3, 0, 0, 1}), 0.75, 1e-12);  // 30-60-90
}

TEST(QualityReference, Quadrilaterals) {
    EXPECT_NEAR(q(CellType::quadrilateral, {0, 0, 1, 0, 1, 1, 0, 1}), 1.0, 1e-12);
    EXPECT_NEAR(q(CellType::quadrilateral, {0, 0, 2, 0, 2, 1, 0, 1}), 0.8, 1e-12);
    EXPECT_NEAR(q(CellType::quadrilateral, {0, 0, 2, 0, 1.5, 1, 0.5, 1}), 32.0 / 39.0, 1e-12);
}

TEST(QualityReference, Tetrahedra) {
    EXPECT_NEAR(ideal_element(CellType::tetrahedron).quality(), 1.0, 1e-12);
    EXPECT_NEAR(q(CellType::tetrahedron, {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1}, 3), 3 * std::cbrt(2.0) / 4.5, 1e-12);
}

TEST(QualityReference, Hexahedra) {
    EXPECT_NEAR(ideal_element(CellType::hexahedron).quality(), 1.0, 1e-12);
    EXPECT_NEAR(q(CellType::hexahedron, {0, 0, 0, 2, 0, 0, 2, 1, 0, 0, 1, 0, 0, 0, 1, 2, 0, 1, 2, 1, 1, 0, 1, 1}, 3),
                3 * std::cbrt(4.0) / 6, 1e-12);
}

TEST(QualityReference, IdealPrismAndPyramidScoreOne) {
    EXPECT_NEAR(ideal_element(CellType::prism).quality(), 1.0, 1e-12);
    EXPECT_NEAR(ideal_element(CellType::pyramid).quality(), 1.0, 1e-12);
}

TEST(QualityReference, NonIdealPrismAndPyramidScoreBelowOne) {
    // A prism twice as tall: corner T has singular values (1, 1, 2), q = 3·2^(2/3)/6 at every corner.
    TestElement tall = ideal_element(CellType::prism);
    for (int n = 3; n < 6; ++n) tall.x[3 * n + 2] = 2;
    EXPECT_NEAR(tall.quality(), 3 * std::cbrt(4.0) / 6, 1e-12);
    // A pyramid with its apex at height 1/2: at the base corners and the apex
    // sub-corners alike α = 1/2 and tr(λ (WᵀW)⁻¹) = 2.5 (hand-computed), so
    // every corner scores 3 (√2/2)^(2/3) / 2.5.
    TestElement low = ideal_element(CellType::pyramid);
    low.x[14] = 0.5;
    EXPECT_NEAR(low.quality(), 3 * std::cbrt(0.5) / 2.5, 1e-12);
}

TEST(QualityReference, VertexAndLineScoreZero) {
    EXPECT_EQ(q(CellType::vertex, {1, 2}), 0.0);
    EXPECT_EQ(q(CellType::line, {0, 0, 1, 0}), 0.0);
}

// ---- properties, for every type -------------------------------------------

TEST(QualityProperties, InvariantUnderTranslationRotationAndScaling) {
    std::mt19937 rng(7);
    for (CellType type : quality_types) {
        SCOPED_TRACE(std::string(cell_type_name(type)));
        for (int trial = 0; trial < 20; ++trial) {
            const TestElement e = test::perturbed(type, rng, 0.15);
            const double reference = e.quality();
            ASSERT_GT(reference, 0.3);
            for (double scale : {1e-3, 1.0, 7.5, 1e3})
                EXPECT_NEAR(test::moved(e, rng, scale).quality(), reference, 1e-12);
        }
    }
}

TEST(QualityProperties, HugeCoordinatesScoreAsSmallOnesNeverNaN) {
    // Issue #27: a mesh moved by 1e308 reported "mean": null (NaN): squared
    // edges overflowed. Scaled by a power of two the metric keeps every bit.
    std::mt19937 rng(11);
    for (CellType type : quality_types) {
        SCOPED_TRACE(std::string(cell_type_name(type)));
        const TestElement e = test::perturbed(type, rng, 0.15);
        for (double scale : {0x1p1000, 0x1p1020}) {
            TestElement big = e;
            for (double& v : big.x) v *= scale;
            EXPECT_EQ(big.quality(), e.quality()) << scale;
            EXPECT_EQ(big.orientation(), e.orientation()) << scale;
        }
        // Nodes at 1e308 that rounding has merged: degenerate, 0, not NaN.
        TestElement far = e;
        for (double& v : far.x) v = 1e308 + v;
        EXPECT_EQ(far.quality(), 0.0);
    }
}

TEST(QualityProperties, MirroredElementWithOrientationMinusOneScoresAsOriginal) {
    std::mt19937 rng(11);
    for (CellType type : quality_types) {
        SCOPED_TRACE(std::string(cell_type_name(type)));
        for (int trial = 0; trial < 10; ++trial) {
            const TestElement e = test::perturbed(type, rng, 0.15);
            const TestElement m = test::mirrored(e);
            EXPECT_EQ(e.orientation(), 1);
            EXPECT_EQ(m.orientation(), -1);
            EXPECT_NEAR(m.quality(-1), e.quality(), 1e-14);
            EXPECT_LE(m.quality(+1), 0.0);  // mirrored against its reference: inverted
            EXPECT_LE(e.quality(-1), 0.0);
        }
    }
}

TEST(QualityProperties, ElementWithANodePushedThroughTheOppositeFaceScoresAtMostZero) {
    // (type, node, coordinate, new value): the node crosses the face/edge opposite it.
    struct Push {
        CellType type;
        int node, coordinate;
        double value;
    };
    const Push pushes[] = {{CellType::triangle, 2, 1, -0.3},   {CellType::quadrilateral, 2, 1, -0.5},
                           {CellType::tetrahedron, 3, 2, -0.3}, {CellType::hexahedron, 4, 2, -0.5},
                           {CellType::prism, 3, 2, -0.5},       {CellType::pyramid, 4, 2, -0.5}};
    for (const Push& p : pushes) {
        SCOPED_TRACE(std::string(cell_type_name(p.type)));
        TestElement e = ideal_element(p.type);
        e.x[p.node * e.dim + p.coordinate] = p.value;
        const double value = e.quality();
        EXPECT_LE(value, 0.0);
        EXPECT_GE(value, -1.0 - 1e-12);
    }
}

TEST(QualityProperties, FlatElementScoresZeroNeverNaN) {
    for (CellType type : quality_types) {
        SCOPED_TRACE(std::string(cell_type_name(type)));
        TestElement flat = ideal_element(type);
        if (flat.dim == 3) {
            for (int n = 0; n < flat.nodes(); ++n) flat.x[3 * n + 2] = 0;  // squashed onto z = 0
        } else {
            for (int n = 0; n < flat.nodes(); ++n) flat.x[2 * n + 1] = 0;  // squashed onto y = 0
        }
        EXPECT_EQ(flat.quality(), 0.0);
        EXPECT_EQ(flat.quality(-1), 0.0);
        TestElement point = ideal_element(type);
        for (double& v : point.x) v = 0.25;  // all nodes on one point
        EXPECT_EQ(point.quality(), 0.0);
        EXPECT_EQ(point.quality(-1), 0.0);
    }
}

TEST(QualityProperties, RandomNodesStayWithinMinusOneAndOneAndAgreeWithOrientation) {
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> u(-1, 1);
    for (CellType type : quality_types) {
        SCOPED_TRACE(std::string(cell_type_name(type)));
        for (int trial = 0; trial < 2000; ++trial) {
            TestElement e = ideal_element(type);
            for (double& v : e.x) v = u(rng);
            for (int orientation : {1, -1}) {
                const double value = e.quality(orientation);
                ASSERT_FALSE(std::isnan(value));
                EXPECT_LE(value, 1.0 + 1e-12);
                EXPECT_GE(value, -1.0 - 1e-12);
                // every corner positive implies a positive signed measure
                if (value > 0) {
                    EXPECT_EQ(e.orientation(), orientation);
                }
            }
        }
    }
}

TEST(QualityProperties, IdealElementsAreOrientedPositively) {
    for (CellType type : quality_types) {
        SCOPED_TRACE(std::string(cell_type_name(type)));
        EXPECT_EQ(ideal_element(type).orientation(), 1);
        EXPECT_EQ(test::mirrored(ideal_element(type)).orientation(), -1);
    }
    EXPECT_EQ(cell_orientation(CellType::line, std::vector<double>{1, 0, 0, 0}, 2), 1);
}

// ---- triangles and quadrilaterals in 3D space --------------------------------

TEST(QualityFacesInSpace, MatchThePlanarValueAndIgnoreOrientation) {
    std::mt19937 rng(5);
    for (CellType type : {CellType::triangle, CellType::quadrilateral}) {
        SCOPED_TRACE(std::string(cell_type_name(type)));
        for (int trial = 0; trial < 10; ++trial) {
            const TestElement planar = test::perturbed(type, rng, 0.15);
            TestElement space{type, 3, {}};
            for (int n = 0; n < planar.nodes(); ++n) space.x.insert(space.x.end(), {planar.x[2 * n], planar.x[2 * n + 1], 0});
            const TestElement spun = test::moved(space, rng, 2.0);
            EXPECT_NEAR(spun.quality(), planar.quality(), 1e-12);
            EXPECT_EQ(spun.quality(-1), spun.quality(1));
            EXPECT_EQ(spun.orientation(), 1);
            EXPECT_NEAR(test::mirrored(spun).quality(), planar.quality(), 1e-12);
        }
    }
}

TEST(QualityFacesInSpace, NonConvexQuadrilateralScoresAtMostZero) {
    const std::vector<double> dart2d = {0, 0, 1, 0, 0.3, 0.3, 0, 1};  // reflex corner at node 2
    EXPECT_LE(q(CellType::quadrilateral, dart2d), 0.0);
    std::vector<double> dart3d;
    for (int n = 0; n < 4; ++n) dart3d.insert(dart3d.end(), {dart2d[2 * n], 0.5 * dart2d[2 * n + 1], dart2d[2 * n + 1]});
    EXPECT_LE(q(CellType::quadrilateral, dart3d, 3), 0.0);
}
