// DG-IDW with continuous weights (DgIdwWeighting::continuous, docs/dg-idw.md):
// each corner's weight times the node's barycentric coordinate, no multipliers.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <vector>

#include "dgwarp/graph/delaunay_graph.hpp"
#include "dgwarp/methods/dg_idw.hpp"
#include "support/box_in_box.hpp"
#include "support/dg_idw_deformed.hpp"

using namespace dgwarp;
using dgwarp::test::box_in_box;
using dgwarp::test::dg_idw_deformed;
using dgwarp::test::BoxInBox;
using dgwarp::test::jittered;
using dgwarp::test::random_motion;

namespace {

constexpr DgIdwOptions continuous{.weighting = DgIdwWeighting::continuous};

// Barycentric coordinates of x in the triangle p0 p1 p2 by Cramer's rule
// (independent of the library's sub-area form).
void cramer_barycentric(const double* p, const double* x, double* e) {
    const double ax = p[2] - p[0], ay = p[3] - p[1], bx = p[4] - p[0], by = p[5] - p[1];
    const double det = ax * by - ay * bx;
    const double rx = x[0] - p[0], ry = x[1] - p[1];
    e[1] = (rx * by - ry * bx) / det;
    e[2] = (ax * ry - ay * rx) / det;
    e[0] = 1 - e[1] - e[2];
}

}  // namespace

TEST(DgIdwContinuous, OneTriangleTranslationMatchesTheHandFormulaForEveryMovingSet) {
    // s = a sum_D e_k r_k^-2 s_k / (a sum_D e_k r_k^-2 + sum_S e_j r_j^-1), r divided by L.
    const std::vector<double> corners{0, 0, 2, 0.2, 0.5, 1.7};
    const double x[2] = {0.8, 0.6};
    double e[3];
    cramer_barycentric(corners.data(), x, e);
    for (double v : e) ASSERT_GT(v, 0.05);
    for (const double length : {1.0, 2.5}) {
        for (unsigned mask = 0; mask < 8; ++mask) {
            std::vector<double> points = corners;
            points.insert(points.end(), x, x + 2);
            BoundarySet boundary{{0, 1, 2}, {}};
            for (int k = 0; k < 3; ++k) boundary.moving.push_back(mask >> k & 1);
            DgIdwOptions options = continuous;
            options.length_scale = length;
            const DgIdwPlan plan = prepare_dg_idw(2, points, boundary, options);
            EXPECT_EQ(plan.options.weighting, DgIdwWeighting::continuous);
            BoundaryMotion motion(3);
            double numerator[2] = {}, moving_sum = 0, static_sum = 0;
            for (int k = 0; k < 3; ++k) {
                const double r = std::hypot(x[0] - corners[2 * k], x[1] - corners[2 * k + 1]) / length;
                if (mask >> k & 1) {
                    motion[k].translation = {0.1 * (k + 1), -0.05 * (k + 2), 0};
                    moving_sum += 7.0 * e[k] / (r * r);
                    for (int d = 0; d < 2; ++d) numerator[d] += 7.0 * e[k] / (r * r) * motion[k].translation[d];
                } else {
                    static_sum += e[k] / r;
                }
            }
            const auto out = dg_idw_deformed(plan, points, motion);
            for (int d = 0; d < 2; ++d) {
                const double expected = mask == 0 ? 0.0 : numerator[d] / (moving_sum + static_sum);
                EXPECT_NEAR(out[6 + d] - x[d], expected, 1e-14) << "mask " << mask << " L " << length;
            }
        }
    }
}

// For every face shared by two graph simplices, a volume node just inside
// each of them (the face's centroid moved 1e-7 of the way towards each
// opposite corner). The paper's weights jump across such a face (its two
// simplices have different other corners and multipliers); the continuous
// ones do not. Returns the largest |difference of the two nodes' displacements|
// over their distance.
double largest_slope_across_faces(int dim, DgIdwWeighting weighting) {
    const BoxInBox m = jittered(box_in_box(dim, dim == 2 ? 12 : 6), 0.01, 7);
    const LocatedGraph lg = build_located_graph(dim, m.points, m.boundary.nodes, {});
    const DelaunayGraph& g = lg.graph;
    const int corners = dim + 1;
    // Faces as sorted vertex lists, with their simplex and opposite corner.
    std::map<std::vector<std::int32_t>, std::vector<std::pair<std::size_t, int>>> faces;
    for (std::size_t s = 0; s < g.num_simplices(); ++s)
        for (int k = 0; k < corners; ++k) {
            std::vector<std::int32_t> face;
            for (int j = 0; j < corners; ++j)
                if (j != k) face.push_back(g.simplices[s * corners + j]);
            std::sort(face.begin(), face.end());
            faces[face].push_back({s, k});
        }
    auto vertex = [&](std::int32_t v) {
        const auto node = static_cast<std::size_t>(m.boundary.nodes[g.vertex_nodes[g.vertex_offsets[v]]]);
        return m.points.data() + node * dim;
    };
    std::vector<double> points(m.points);
    std::vector<NodeId> pairs;  // first node of each pair
    for (const auto& [face, sides] : faces) {
        if (sides.size() != 2) continue;  // a hull face
        double centroid[3] = {};
        for (std::int32_t v : face)
            for (int d = 0; d < dim; ++d) centroid[d] += vertex(v)[d] / dim;
        pairs.push_back(static_cast<NodeId>(points.size() / dim));
        for (const auto& [s, k] : sides) {
            const double* opposite = vertex(g.simplices[s * corners + k]);
            for (int d = 0; d < dim; ++d) points.push_back(centroid[d] + 1e-7 * (opposite[d] - centroid[d]));
        }
    }
    // The volume nodes of m are dropped from the boundary set's point of view:
    // they stay volume nodes, which is all the plan needs.
    const DgIdwPlan plan = prepare_dg_idw(dim, points, m.boundary, {.weighting = weighting});
    BoxInBox with_pairs = m;
    with_pairs.points = points;
    const BoundaryMotion motion = random_motion(with_pairs, 3, 0.05);
    const auto out = dg_idw_deformed(plan, points, motion);
    double worst = 0;
    for (NodeId p : pairs) {
        const auto a = static_cast<std::size_t>(p), b = a + 1;
        double jump = 0, distance = 0;
        for (int d = 0; d < dim; ++d) {
            jump = std::max(jump, std::abs((out[b * dim + d] - points[b * dim + d]) - (out[a * dim + d] - points[a * dim + d])));
            distance += (points[b * dim + d] - points[a * dim + d]) * (points[b * dim + d] - points[a * dim + d]);
        }
        worst = std::max(worst, jump / std::sqrt(distance));
    }
    EXPECT_GT(pairs.size(), 20u);
    return worst;
}

TEST(DgIdwContinuous, NoJumpAcrossGraphFacesWhereThePaperWeightsJump) {
    for (int dim : {2, 3}) {
        const double paper = largest_slope_across_faces(dim, DgIdwWeighting::paper);
        const double smooth = largest_slope_across_faces(dim, DgIdwWeighting::continuous);
        // A jump J between nodes ~1e-8 apart shows as a slope of J * 1e8;
        // a continuous field has the slope of its gradient, O(motion / distance).
        EXPECT_GT(paper, 1e3) << dim << "D";
        EXPECT_LT(smooth, 50.0) << dim << "D";
    }
}

