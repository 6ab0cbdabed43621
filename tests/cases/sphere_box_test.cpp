#include "dgwarp/cases/sphere_box.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "dgwarp/core/error.hpp"
#include "dgwarp/quality/mesh_quality.hpp"

using namespace dgwarp;

namespace {
// Coarse sizes, so the test takes a second; the paper's sizes are built by `dgwarp bench`.
SphereBoxOptions coarse_options() { return {0.25, 1.5, 0.2, 1.5, 1}; }
}  // namespace

TEST(CasesSphereBox, CoarseMeshIsValidPositiveAndDeterministic) {
    const Mesh m = make_sphere_box(coarse_options());
    EXPECT_EQ(m.dim, 3);
    EXPECT_NO_THROW(validate(m));
    EXPECT_GT(m.cells.size(), 1000u);
    const QualitySummary q = summarize_quality(cell_qualities(m, std::vector<std::int8_t>(m.cells.size(), 1)));
    EXPECT_EQ(q.inverted, 0);
    EXPECT_GT(q.min, 0.0);
    EXPECT_TRUE(make_sphere_box(coarse_options()) == m);
}

TEST(CasesSphereBox, MarkersLieOnTheSphereAndTheBox) {
    const Mesh m = make_sphere_box(coarse_options());
    const auto sphere = marker_nodes(find_marker(m, "sphere"));
    const auto box = marker_nodes(find_marker(m, "box"));
    EXPECT_GT(sphere.size(), 50u);
    EXPECT_GT(box.size(), 50u);
    for (NodeId n : sphere)
        EXPECT_NEAR(std::hypot(m.points[3 * n], m.points[3 * n + 1], m.points[3 * n + 2]), 1.0, 1e-6);
    for (NodeId n : box)
        EXPECT_NEAR(std::max({std::abs(m.points[3 * n]), std::abs(m.points[3 * n + 1]), std::abs(m.points[3 * n + 2])}),
                    5.0, 1e-9);
}

TEST(CasesSphereBox, PaperSizesAreKnownAndBadOptionsThrow) {
    EXPECT_LT(sphere_box_paper_size(2).h_sphere, sphere_box_paper_size(0).h_sphere);
    EXPECT_THROW(sphere_box_paper_size(3), MeshError);
    SphereBoxOptions o = coarse_options();
    o.growth = 0;
    EXPECT_THROW(make_sphere_box(o), MeshError);
}
