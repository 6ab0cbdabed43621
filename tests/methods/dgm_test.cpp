// DGM (Delaunay graph mapping): barycentric coordinates, exact boundary
// motion, affine and rigid reproduction, thread independence, shared vertices.
#include "dgwarp/methods/dgm.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "dgwarp/core/error.hpp"
#include "support/box_in_box.hpp"

using namespace dgwarp;
using dgwarp::test::all_moving;
using dgwarp::test::box_in_box;
using dgwarp::test::BoxInBox;

namespace {

std::vector<double> deform(const DgmPlan& plan, const std::vector<double>& points, const BoundaryMotion& motion,
                           const DgmOptions& options = {}, DgmStepReport* report = nullptr) {
    std::vector<double> out(points.size(), std::nan(""));
    const DgmStepReport r = deform_dgm(plan, points, motion, out, options);
    if (report) *report = r;
    return out;
}

// A random affine map x -> A x + b with det A > 0 (so the graph stays valid), row-major A.
struct Affine {
    double a[9];
    double b[3];
};

Affine random_affine(int dim, std::uint32_t seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> u(-0.4, 0.4);
    Affine f{};
    for (int i = 0; i < dim; ++i) {
        for (int j = 0; j < dim; ++j) f.a[i * 3 + j] = (i == j ? 1.0 : 0.0) + u(rng);
        f.b[i] = u(rng);
    }
    return f;
}

std::vector<double> apply_affine(int dim, const Affine& f, const double* x) {
    std::vector<double> y(static_cast<std::size_t>(dim));
    for (int i = 0; i < dim; ++i) {
        y[i] = f.b[i];
        for (int j = 0; j < dim; ++j) y[i] += f.a[i * 3 + j] * x[j];
    }
    return y;
}

// The affine map as per-node translations t_i = A x_i + b - x_i.
BoundaryMotion affine_motion(int dim, const Affine& f, const std::vector<double>& points, const BoundarySet& boundary) {
    BoundaryMotion motion(boundary.nodes.size());
    for (std::size_t b = 0; b < motion.size(); ++b) {
        const double* x = points.data() + static_cast<std::size_t>(boundary.nodes[b]) * dim;
        const auto y = apply_affine(dim, f, x);
        for (int d = 0; d < dim; ++d) motion[b].translation[d] = y[d] - x[d];
    }
    return motion;
}

}  // namespace

TEST(DgmPrepare, BarycentricCoordinatesSumToOneAndReproduceEveryVolumeNode) {
    for (int dim : {2, 3}) {
        const BoxInBox m = test::jittered(box_in_box(dim, dim == 2 ? 24 : 9, 2.0), 0.01, 5);
        const DgmPlan plan = prepare_dgm(dim, m.points, m.boundary);
        ASSERT_EQ(plan.num_volume_nodes(), static_cast<std::int64_t>(m.volume.size()));
        ASSERT_EQ(plan.node_barycentric.size(), m.volume.size() * (dim + 1));
        for (std::size_t i = 0; i < m.volume.size(); ++i) {
            const NodeId n = m.volume[i];
            const std::int32_t s = plan.node_simplex[n];
            ASSERT_GE(s, 0);
            const double* e = plan.node_barycentric.data() + i * (dim + 1);
            double sum = 0, x[3] = {};
            for (int k = 0; k <= dim; ++k) {
                const std::int32_t v = plan.simplices[static_cast<std::size_t>(s) * (dim + 1) + k];
                const std::int32_t b = plan.vertex_motion[v] >= 0 ? plan.vertex_motion[v] : -1 - plan.vertex_motion[v];
                const double* p = m.points.data() + static_cast<std::size_t>(m.boundary.nodes[b]) * dim;
                sum += e[k];
                for (int d = 0; d < dim; ++d) x[d] += e[k] * p[d];
                // Inside the hull, every coordinate is in [0, 1] (up to round-off).
                EXPECT_GE(e[k], -1e-12) << dim << "D node " << n;
            }
            EXPECT_NEAR(sum, 1.0, 1e-14);
            for (int d = 0; d < dim; ++d) EXPECT_NEAR(x[d], m.points[n * dim + d], 1e-13) << dim << "D node " << n;
        }
        EXPECT_EQ(plan.stats.outside_count, 0);
        EXPECT_EQ(plan.stats.shared_vertex_count, 0);
    }
}

TEST(DgmPrepare, BarycentricCoordinatesOfOneTriangleAreItsAreaRatios) {
    // Triangle (0,0), (4,0), (0,2) (area 4); node (1, 0.5). Sub-areas by hand:
    // opposite (0,0): triangle (1,0.5),(4,0),(0,2), area 2; opposite (4,0): 1; opposite (0,2): 1.
    const std::vector<double> points = {0, 0, 4, 0, 0, 2, 1, 0.5};
    const BoundarySet boundary{{0, 1, 2}, {1, 0, 0}};
    const DgmPlan plan = prepare_dgm(2, points, boundary);
    ASSERT_EQ(plan.simplices.size(), 3u);
    const double expected_by_node[3] = {0.5, 0.25, 0.25};
    for (int k = 0; k < 3; ++k) {
        const std::int32_t v = plan.simplices[k];
        const std::int32_t b = plan.vertex_motion[v] >= 0 ? plan.vertex_motion[v] : -1 - plan.vertex_motion[v];
        EXPECT_NEAR(plan.node_barycentric[k], expected_by_node[b], 1e-15) << "corner " << k;
    }
    // Moving corner 0 by (1, 1) moves the node by e_0 (1, 1).
    BoundaryMotion motion(3);
    motion[0].translation = {1, 1, 0};
    const auto out = deform(plan, points, motion);
    EXPECT_NEAR(out[6], 1 + 0.5, 1e-15);
    EXPECT_NEAR(out[7], 0.5 + 0.5, 1e-15);
}

TEST(DgmDeform, AnAffineMotionOfTheBoundaryIsReproducedForEveryVolumeNode) {
    for (int dim : {2, 3}) {
        const BoxInBox m = all_moving(test::jittered(box_in_box(dim, dim == 2 ? 24 : 9, 1.5), 0.01, 8));
        const DgmPlan plan = prepare_dgm(dim, m.points, m.boundary);
        for (std::uint32_t seed : {1u, 2u, 3u}) {
            const Affine f = random_affine(dim, seed);
            DgmStepReport report;
            const auto out = deform(plan, m.points, affine_motion(dim, f, m.points, m.boundary), {}, &report);
            ASSERT_EQ(report.invalid_simplices, 0) << "det A > 0 keeps every simplex positive";
            for (NodeId n : m.volume) {
                const auto y = apply_affine(dim, f, m.points.data() + n * dim);
                for (int d = 0; d < dim; ++d) ASSERT_NEAR(out[n * dim + d], y[d], 1e-12) << dim << "D node " << n;
            }
        }
    }
}

TEST(DgmDeform, NodesOutsideTheHullAreExtrapolatedAndCounted) {
    // Boundary: a triangle; volume nodes: one inside, two outside the hull.
    const std::vector<double> points = {0, 0, 2, 0, 0, 2, 0.5, 0.5, 2, 2, -0.5, 0.7};
    const BoundarySet boundary{{0, 1, 2}, {1, 1, 1}};
    const DgmPlan plan = prepare_dgm(2, points, boundary);
    EXPECT_EQ(plan.stats.outside_count, 2);
    // Outside the hull some coordinates are negative, and they still reproduce
    // affine motions (they sum to 1 and reproduce the node).
    EXPECT_LT(*std::min_element(plan.node_barycentric.begin(), plan.node_barycentric.end()), 0);
    const Affine f = random_affine(2, 4);
    const auto out = deform(plan, points, affine_motion(2, f, points, boundary));
    for (std::size_t n = 3; n < 6; ++n) {
        const auto y = apply_affine(2, f, points.data() + 2 * n);
        EXPECT_NEAR(out[2 * n], y[0], 1e-13) << "node " << n;
        EXPECT_NEAR(out[2 * n + 1], y[1], 1e-13) << "node " << n;
    }
}

TEST(DgmDeform, BoundaryNodesSharingCoordinatesAreOneVertexThatFollowsTheMovingOne) {
    const BoxInBox m = box_in_box(2, 12);
    // A copy of the first moving node as a new, static boundary node (last id).
    BoxInBox dup = m;
    const auto first_moving = static_cast<std::size_t>(
        std::find(m.boundary.moving.begin(), m.boundary.moving.end(), 1) - m.boundary.moving.begin());
    const NodeId original = m.boundary.nodes[first_moving];
    const auto copy = static_cast<NodeId>(m.num_points());
    dup.points.push_back(m.points[2 * original]);
    dup.points.push_back(m.points[2 * original + 1]);
    dup.boundary.nodes.push_back(copy);
    dup.boundary.moving.push_back(0);

    const DgmPlan plan = prepare_dgm(2, m.points, m.boundary);
    const DgmPlan plan_dup = prepare_dgm(2, dup.points, dup.boundary);
    EXPECT_EQ(plan_dup.stats.shared_vertex_count, 1);
    EXPECT_EQ(plan_dup.simplices.size(), plan.simplices.size());

    BoundaryMotion motion(m.boundary.nodes.size());
    for (std::size_t b = 0; b < motion.size(); ++b)
        if (m.boundary.moving[b]) motion[b].translation = {0.02, -0.01, 0};
    BoundaryMotion motion_dup = motion;
    motion_dup.push_back(NodeMotion{});  // the static copy
    const auto out = deform(plan, m.points, motion);
    DgmStepReport report;
    const auto out_dup = deform(plan_dup, dup.points, motion_dup, {}, &report);
    EXPECT_EQ(report.conflicting_shared_vertices, 1);
    // Volume nodes move as if the copy were not there; the copy stays put.
    for (NodeId n : m.volume)
        for (int d = 0; d < 2; ++d) EXPECT_NEAR(out_dup[2 * n + d], out[2 * n + d], 1e-15) << "node " << n;
    EXPECT_EQ(out_dup[2 * copy], m.points[2 * original]);
    EXPECT_EQ(out_dup[2 * copy + 1], m.points[2 * original + 1]);
    EXPECT_EQ(out_dup[2 * original], out[2 * original]);
}

TEST(DgmDeform, RejectsMismatchedSizesAndBadOptions) {
    const BoxInBox m = box_in_box(2, 12);
    const DgmPlan plan = prepare_dgm(2, m.points, m.boundary);
    std::vector<double> out(m.points.size());
    EXPECT_THROW(deform_dgm(plan, m.points, BoundaryMotion(3), out), MeshError);
    std::vector<double> short_out(m.points.size() - 2);
    EXPECT_THROW(deform_dgm(plan, m.points, BoundaryMotion(m.boundary.nodes.size()), short_out), MeshError);
    EXPECT_THROW(deform_dgm(plan, m.points, BoundaryMotion(m.boundary.nodes.size()), out, {.max_substeps = 0}), Error);
    EXPECT_THROW(prepare_dgm(4, m.points, m.boundary), MeshError);
    BoundarySet unsorted = m.boundary;
    std::swap(unsorted.nodes[0], unsorted.nodes[1]);
    EXPECT_THROW(prepare_dgm(2, m.points, unsorted), MeshError);
}
