// The displacement a job's motion gives its boundary nodes
// (job/boundary_displacement.hpp): the moving nodes' by their motion, the
// fixed ones' zero, and a 2D case's on both planes of the file's mesh.
#include "dgwarp/job/boundary_displacement.hpp"

#include <gtest/gtest.h>

#include "dgwarp/io/motion_file.hpp"
#include "io/openfoam/openfoam_test_support.hpp"
#include "support/small_grid_with_hole.hpp"

using namespace dgwarp;
using namespace dgwarp::test;

TEST(BoundaryDisplacement, TheMovingNodesMoveByTheirMotionTheOthersNot) {
    JobInputs in;
    in.mesh = small_grid_with_hole();
    for (double dy : {0.1, 0.3}) {
        MotionFrame frame;
        frame.markers["rectangle"] = RigidMotion{NodeMotion{{0, dy, 0}, {}, {}}};
        in.spec.frames.push_back(frame);
    }
    classify_inputs(in, {});
    const BoundaryDisplacement d = boundary_displacement(in, 1);
    ASSERT_EQ(d.displacement.size(), in.mesh.points.size());
    EXPECT_EQ(d.boundary.nodes, in.boundary.boundary.nodes);
    std::size_t moving = 0;
    for (std::size_t b = 0; b < d.boundary.nodes.size(); ++b) {
        const auto v = static_cast<std::size_t>(d.boundary.nodes[b]);
        moving += d.boundary.moving[b];
        EXPECT_EQ(d.displacement[2 * v], 0.0);
        EXPECT_NEAR(d.displacement[2 * v + 1], d.boundary.moving[b] ? 0.3 : 0.0, 1e-15) << "node " << v;
    }
    EXPECT_GT(moving, 0u);
}

TEST(BoundaryDisplacement, A2dCasesNodesMoveOnBothPlanes) {
    JobInputs in;
    in.mesh = read_mesh(openfoam_case("cavity"), {}, {}, in.extras);
    in.spec = parse_motion_file(R"({"markers": {"movingWall": {"translate": [0.001, 0, 0]}}})", "m.json",
                                std::filesystem::temp_directory_path());
    classify_inputs(in, {});
    ASSERT_TRUE(in.planar);
    const BoundaryDisplacement d = boundary_displacement(in, 0);
    const Mesh& file = output_mesh(in);
    ASSERT_EQ(d.displacement.size(), file.points.size());
    // Every boundary node of the 2D mesh has its two twins in the file's.
    EXPECT_EQ(d.boundary.nodes.size(), 2 * in.boundary.boundary.nodes.size());
    std::size_t moving = 0;
    for (std::size_t b = 0; b < d.boundary.nodes.size(); ++b) {
        const auto v = static_cast<std::size_t>(d.boundary.nodes[b]);
        moving += d.boundary.moving[b];
        EXPECT_NEAR(d.displacement[3 * v], d.boundary.moving[b] ? 0.001 : 0.0, 1e-15) << "node " << v;
        EXPECT_NEAR(d.displacement[3 * v + 1], 0.0, 1e-15);
        EXPECT_NEAR(d.displacement[3 * v + 2], 0.0, 1e-15);
    }
    EXPECT_GT(moving, 0u);
}

TEST(BoundaryDisplacement, SlidingNodesMoveInTheirPlanesByTheFirstPass) {
    JobInputs in;
    in.mesh = small_grid_with_hole();
    MotionFrame frame;
    frame.markers["rectangle"] = RigidMotion{NodeMotion{{0, 0.3, 0}, {}, {}}};
    frame.markers["farfield"] = SlideMotion{};
    in.spec.frames.push_back(frame);
    classify_inputs(in, {});
    ASSERT_FALSE(in.boundary.slides.empty());
    const BoundaryDisplacement d = boundary_displacement(in, 0);
    // The outer box's sides: each node moves along its side (a corner not at all), and some do move.
    double lo[2] = {1e300, 1e300}, hi[2] = {-1e300, -1e300};
    for (std::size_t v = 0; v < in.mesh.points.size() / 2; ++v)
        for (int k = 0; k < 2; ++k) {
            lo[k] = std::min(lo[k], in.mesh.points[2 * v + k]);
            hi[k] = std::max(hi[k], in.mesh.points[2 * v + k]);
        }
    double largest = 0;
    for (std::size_t b = 0; b < d.boundary.nodes.size(); ++b) {
        if (d.boundary.moving[b] == 0) continue;
        const auto v = static_cast<std::size_t>(d.boundary.nodes[b]);
        for (int k = 0; k < 2; ++k) {
            const double x = in.mesh.points[2 * v + k];
            if (x != lo[k] && x != hi[k]) continue;  // not on a side normal to axis k
            EXPECT_EQ(d.displacement[2 * v + k], 0.0) << "node " << v << " leaves its side";
        }
        const bool on_box = in.mesh.points[2 * v] == lo[0] || in.mesh.points[2 * v] == hi[0] ||
                            in.mesh.points[2 * v + 1] == lo[1] || in.mesh.points[2 * v + 1] == hi[1];
        if (on_box) largest = std::max({largest, std::abs(d.displacement[2 * v]), std::abs(d.displacement[2 * v + 1])});
    }
    EXPECT_GT(largest, 1e-6);  // the first pass slid them
}
