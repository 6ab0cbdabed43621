// The planes sliding nodes stay in (slide_planes.hpp), checked on a lattice
// box whose faces are the coordinate planes, where every answer is exact.
#include "dgwarp/motion/slide_planes.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "dgwarp/core/error.hpp"
#include "dgwarp/motion/motion_spec.hpp"
#include "dgwarp/motion/resolve_motion.hpp"
#include "support/lattice_box.hpp"

namespace dgwarp {
namespace {

using test::lattice_box;

std::vector<NodeId> nodes_of(const Mesh& m, std::initializer_list<const char*> names) {
    std::vector<NodeId> out;
    for (const Marker& marker : m.markers)
        if (std::find_if(names.begin(), names.end(), [&](const char* n) { return marker.name == n; }) != names.end()) {
            const auto ids = marker_nodes(marker);
            out.insert(out.end(), ids.begin(), ids.end());
        }
    std::sort(out.begin(), out.end());
    out.erase(std::unique(out.begin(), out.end()), out.end());
    return out;
}

std::size_t marker_index(const Mesh& m, const char* name) {
    for (std::size_t i = 0; i < m.markers.size(); ++i)
        if (m.markers[i].name == name) return i;
    return m.markers.size();
}

TEST(SlidePlanes, AFaceNodeMovesInItsPlaneAnEdgeNodeAlongItsLine) {
    const Mesh m = lattice_box(3, 4);  // node i + 4 (j + 4 k) at (i, j, k) / 3
    const std::size_t sliding[] = {marker_index(m, "x_m"), marker_index(m, "y_m")};
    const std::vector<NodeId> held = nodes_of(m, {"x_p", "y_p", "z_m", "z_p"});
    const SlidePlanes p = slide_planes(m, sliding, held);
    EXPECT_TRUE(p.corners.empty());
    // x_m and y_m without the held nodes: 2 x 2 inner nodes each, and the 2 inner nodes of their common edge.
    ASSERT_EQ(p.slides.size(), 10u);
    for (std::size_t i = 0; i < p.slides.size(); ++i) {
        const NodeId node = p.slides.nodes[i];
        const int x = node % 4, y = node / 4 % 4;
        const double* u = &p.slides.directions[3 * i];
        if (x == 0 && y == 0) {  // the edge: along z
            EXPECT_EQ(p.slides.planes[i], 2) << node;
            EXPECT_EQ(std::abs(u[2]), 1.0) << node;
        } else {  // a face: normal x (x_m) or y (y_m)
            EXPECT_EQ(p.slides.planes[i], 1) << node;
            EXPECT_EQ(std::abs(u[x == 0 ? 0 : 1]), 1.0) << node;
        }
        for (int d = 0; d < 3; ++d) EXPECT_EQ(p.slides.origins[3 * i + d], m.points[3 * node + d]);
    }
}

TEST(SlidePlanes, WhereThreePlanesMeetTheNodeIsACorner) {
    const Mesh m = lattice_box(3, 3);
    std::vector<std::size_t> all(m.markers.size());
    for (std::size_t i = 0; i < all.size(); ++i) all[i] = i;
    const SlidePlanes p = slide_planes(m, all, {});
    EXPECT_EQ(p.corners.size(), 8u);  // the box's corners
    EXPECT_EQ(p.slides.size(), 26u - 8u);
    EXPECT_EQ(std::count(p.slides.planes.begin(), p.slides.planes.end(), 2), 12);  // the edges' middles
    // 2D: where two lines meet.
    const Mesh s = lattice_box(2, 3);
    const std::size_t two[] = {0, 2};  // x_m, y_m: they meet at node 0
    const SlidePlanes q = slide_planes(s, two, {});
    EXPECT_EQ(q.corners, std::vector<NodeId>{0});
}

TEST(SlidePlanes, ACurvedMarkerIsAnErrorNamingItAndTheNode) {
    Mesh m = lattice_box(3, 4);
    // Node (0, 1, 1) / 3 moved off the plane x = 0 by 1e-4: its faces meet at about 0.02 degrees.
    const NodeId bent = 0 + 4 * (1 + 4 * 1);
    m.points[3 * bent] = 1e-4;
    const std::size_t sliding[] = {marker_index(m, "x_m")};
    try {
        slide_planes(m, sliding, nodes_of(m, {"x_p", "y_m", "y_p", "z_m", "z_p"}));
        FAIL() << "a curved sliding marker was accepted";
    } catch (const MeshError& e) {
        EXPECT_EQ(e.marker(), "x_m");
        EXPECT_NE(std::string(e.what()).find("not planar"), std::string::npos) << e.what();
        const NodeId around[] = {bent, 0 + 4 * (2 + 4 * 1), 0 + 4 * (1 + 4 * 2), 0 + 4 * (2 + 4 * 2)};
        EXPECT_NE(std::find(std::begin(around), std::end(around), e.index()), std::end(around)) << e.index();
    }
}

TEST(SlidePlanes, ApplyKeepsThePartInThePlaneOrAlongTheLine) {
    const Mesh m = lattice_box(3, 4);
    const std::size_t sliding[] = {marker_index(m, "x_m"), marker_index(m, "y_m")};
    const SlidePlanes p = slide_planes(m, sliding, nodes_of(m, {"x_p", "y_p", "z_m", "z_p"}));
    std::vector<double> points = m.points;
    for (double& v : points) v += 0.0625;  // every node moved by (1, 1, 1) / 16
    apply_slides(p.slides, 3, points);
    for (std::size_t i = 0; i < p.slides.size(); ++i) {
        const auto node = static_cast<std::size_t>(p.slides.nodes[i]);
        const double* x = &points[3 * node];
        const double* x0 = &m.points[3 * node];
        const bool edge = p.slides.planes[i] == 2;
        const bool on_x = x0[0] == 0;
        // Exactly: the removed parts are whole components along the axes.
        EXPECT_EQ(x[0], on_x ? x0[0] : x0[0] + 0.0625) << node;
        EXPECT_EQ(x[1], on_x && !edge ? x0[1] + 0.0625 : x0[1]) << node;
        EXPECT_EQ(x[2], x0[2] + 0.0625) << node;
    }
    // The same projection on vectors: what apply_slides did to each node's displacement.
    std::vector<double> per_node(p.slides.size() * 3, 0.0625);
    project_slide_vectors(p.slides, 3, per_node);
    for (std::size_t i = 0; i < p.slides.size(); ++i)
        for (std::size_t d = 0; d < 3; ++d) {
            const auto at = 3 * static_cast<std::size_t>(p.slides.nodes[i]) + d;
            EXPECT_NEAR(per_node[3 * i + d], points[at] - m.points[at], 1e-15);
        }
}

TEST(SlidePlanes, ResolvedSlidingNodesAreMovingBoundaryNodesAndCornersStay) {
    const Mesh m = lattice_box(2, 4);
    MotionSpec spec;
    MotionFrame frame;
    frame.markers["y_p"] = RigidMotion{NodeMotion{{0, -0.1, 0}, {0, 0, 0}, {0, 0, 0}}};
    frame.markers["x_m"] = SlideMotion{};
    frame.markers["x_p"] = SlideMotion{};
    frame.markers["y_m"] = SlideMotion{};
    spec.frames.push_back(frame);
    const ResolvedBoundary r = resolve_boundary(m, spec);
    EXPECT_EQ(r.sliding_markers, (std::vector<std::string>{"x_m", "x_p", "y_m"}));
    EXPECT_EQ(r.moving_markers, std::vector<std::string>{"y_p"});
    // x_m and x_p: 2 inner nodes each; y_m: 2 inner nodes; its ends (0, 0) and (1, 0) are corners.
    ASSERT_EQ(r.slides.size(), 6u);
    for (std::size_t i = 0; i < r.slides.size(); ++i) {
        const auto b = static_cast<std::size_t>(r.slides.slots[i]);
        EXPECT_EQ(r.boundary.nodes[b], r.slides.nodes[i]);
        EXPECT_EQ(r.boundary.moving[b], 1);
    }
    for (const NodeId corner : {NodeId{0}, NodeId{3}}) {
        const auto b = std::lower_bound(r.boundary.nodes.begin(), r.boundary.nodes.end(), corner) - r.boundary.nodes.begin();
        EXPECT_EQ(r.boundary.moving[static_cast<std::size_t>(b)], 0) << corner;
    }
    // A marker that slides in one frame of two.
    MotionSpec two = spec;
    MotionFrame other = frame;
    other.markers["x_m"] = FixedMotion{};
    two.frames.push_back(other);
    try {
        resolve_boundary(m, two);
        FAIL() << "a marker sliding in one frame of two was accepted";
    } catch (const MeshError& e) {
        EXPECT_EQ(e.marker(), "x_m");
        EXPECT_NE(std::string(e.what()).find("slides in 1 of the 2 frames"), std::string::npos) << e.what();
    }
}

}  // namespace
}  // namespace dgwarp
