// NearestBoundaryCells (nearest_boundary_cells.hpp) and the coarse wants built
// on it (coarse_points.hpp): bounds against brute force, answers that depend
// on the query point only.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include "dgwarp/core/parallel_for.hpp"
#include "dgwarp/graph/nearest_node.hpp"
#include "dgwarp/methods/coarse_points.hpp"
#include "dgwarp/methods/nearest_boundary_cells.hpp"
#include "support/box_in_box.hpp"

using namespace dgwarp;

namespace {

// Boundary nodes on a circle / sphere of radius 1 (cospherical: the k-d
// tree's hardest case) plus a few on a box around it, and query points
// scattered between them.
struct CellsScene {
    int dim;
    std::vector<double> points;  // boundary nodes first
    std::vector<NodeId> boundary, queries;
};

CellsScene cells_scene(int dim, int boundary_count, int query_count, unsigned seed) {
    CellsScene s{dim, {}, {}, {}};
    std::mt19937 rng(seed);
    std::normal_distribution<double> normal;
    std::uniform_real_distribution<double> uniform(-3, 3);
    for (int i = 0; i < boundary_count; ++i) {
        double x[3], r = 0;
        for (int d = 0; d < dim; ++d) {
            x[d] = normal(rng);
            r += x[d] * x[d];
        }
        for (int d = 0; d < dim; ++d) s.points.push_back(x[d] / std::sqrt(r));
        s.boundary.push_back(i);
    }
    for (int i = 0; i < 8; ++i) {  // corners of the outer box
        for (int d = 0; d < dim; ++d) s.points.push_back((i >> d) & 1 ? 3.0 : -3.0);
        s.boundary.push_back(boundary_count + i);
    }
    const auto first_query = static_cast<NodeId>(s.points.size() / dim);
    for (int i = 0; i < query_count; ++i) {
        for (int d = 0; d < dim; ++d) s.points.push_back(uniform(rng));
        s.queries.push_back(first_query + i);
    }
    return s;
}

double cells_brute_nearest(const CellsScene& s, NodeId q) {
    double best = std::numeric_limits<double>::infinity();
    for (NodeId b : s.boundary) {
        double d2 = 0;
        for (int d = 0; d < s.dim; ++d) d2 += std::pow(s.points[q * s.dim + d] - s.points[b * s.dim + d], 2);
        best = std::min(best, std::sqrt(d2));
    }
    return best;
}

std::vector<double> cells_spacings(const NearestNode& tree, std::size_t n) {
    std::vector<double> h(n);
    for (std::size_t j = 0; j < n; ++j) h[j] = tree.spacing(static_cast<std::int64_t>(j));
    return h;
}

}  // namespace

TEST(NearestBoundaryCells, BoundsHoldAgainstBruteForceIn2DAnd3D) {
    for (int dim : {2, 3}) {
        const CellsScene s = cells_scene(dim, dim == 2 ? 400 : 2000, 20000, 11);
        const NearestNode tree(dim, s.points, s.boundary);
        const std::vector<double> h = cells_spacings(tree, s.boundary.size());
        NearestBoundaryCells cells(dim, s.points, s.boundary, tree, h, CoarseSpacing{});
        int inside = 0;
        for (NodeId q : s.queries) {
            const double* x = s.points.data() + static_cast<std::size_t>(q) * dim;
            const NearestBoundaryCells::Answer a = cells.find(x);
            ASSERT_GE(a.index, 0) << "query " << q << " is inside the boundary's box";
            ++inside;
            const double exact = cells_brute_nearest(s, q);
            double d2 = 0;
            for (int d = 0; d < dim; ++d) d2 += std::pow(x[d] - s.points[s.boundary[a.index] * dim + d], 2);
            EXPECT_DOUBLE_EQ(a.distance, std::sqrt(d2)) << q;
            EXPECT_GE(a.distance, exact) << q;
            EXPECT_LE(a.lower_bound, exact) << q;
        }
        EXPECT_EQ(inside, static_cast<int>(s.queries.size()));
        // Far fewer cells than queries: the point of it.
        EXPECT_LT(cells.num_cells(), s.queries.size() / 2) << "dim " << dim;
    }
}

TEST(NearestBoundaryCells, AnswersDependOnThePointOnlyNotOnTheOtherQueries) {
    const CellsScene s = cells_scene(3, 1500, 2000, 5);
    const NearestNode tree(3, s.points, s.boundary);
    const std::vector<double> h = cells_spacings(tree, s.boundary.size());
    NearestBoundaryCells forward(3, s.points, s.boundary, tree, h, CoarseSpacing{});
    std::vector<NearestBoundaryCells::Answer> a;
    for (NodeId q : s.queries) a.push_back(forward.find(s.points.data() + 3 * static_cast<std::size_t>(q)));
    std::vector<std::size_t> order(s.queries.size());
    for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
    std::shuffle(order.begin(), order.end(), std::mt19937(3));
    NearestBoundaryCells shuffled(3, s.points, s.boundary, tree, h, CoarseSpacing{});
    for (std::size_t i : order) {
        // Every other query alone in a fresh tree too.
        const double* x = s.points.data() + 3 * static_cast<std::size_t>(s.queries[i]);
        const NearestBoundaryCells::Answer b = shuffled.find(x);
        EXPECT_EQ(b.index, a[i].index) << i;
        EXPECT_EQ(b.distance, a[i].distance) << i;
        EXPECT_EQ(b.lower_bound, a[i].lower_bound) << i;
        if (i % 97 == 0) {
            NearestBoundaryCells alone(3, s.points, s.boundary, tree, h, CoarseSpacing{});
            EXPECT_EQ(alone.find(x).index, a[i].index) << i;
        }
    }
}

TEST(NearestBoundaryCells, PointsOutsideTheBoundarysBoxAreLeftToTheCaller) {
    const CellsScene s = cells_scene(2, 100, 0, 2);
    const NearestNode tree(2, s.points, s.boundary);
    const std::vector<double> h = cells_spacings(tree, s.boundary.size());
    NearestBoundaryCells cells(2, s.points, s.boundary, tree, h, CoarseSpacing{});
    const double outside[2] = {3.5, 0}, corner[2] = {3, 3};
    EXPECT_EQ(cells.find(outside).index, -1);
    EXPECT_GE(cells.find(corner).index, 0);
    // One boundary point: no box at all.
    const std::vector<NodeId> one{0};
    NearestBoundaryCells single(2, s.points, one, tree, h, CoarseSpacing{});
    EXPECT_EQ(single.find(corner).index, -1);
}

TEST(CoarseWants, ANodesWantIsTheSameInAnySubsetOfTheVolumeNodes) {
    // What the MPI path relies on: each process computes the wants of its own
    // nodes, and they must be the one-process run's.
    const test::BoxInBox m = test::jittered(test::box_in_box(3, 16), 0.2 / 16, 4);
    const CoarseSpacing spacing{2.0, 0.5};
    const CoarseWants all = coarse_wants(3, m.points, m.boundary.nodes, m.volume, spacing);
    ASSERT_GT(std::count_if(all.want.begin(), all.want.end(), [](double w) { return w > 0; }), 20);
    for (int part = 0; part < 3; ++part) {
        std::vector<NodeId> mine;
        std::vector<double> expected;
        for (std::size_t i = 0; i < m.volume.size(); ++i)
            if (static_cast<int>((m.volume[i] * 2654435761u) % 3) == part) {
                mine.push_back(m.volume[i]);
                expected.push_back(all.want[i]);
            }
        EXPECT_EQ(coarse_wants(3, m.points, m.boundary.nodes, mine, spacing).want, expected) << part;
    }
}

TEST(CoarseWants, WantsAndCoarsePointsDoNotDependOnTheThreadCount) {
    // 27.6k volume nodes: runs of at least 4096 nodes on up to 6 threads, each
    // with cells of its own, and their winners merged.
    const test::BoxInBox m = test::jittered(test::box_in_box(3, 32), 0.2 / 32, 5);
    ASSERT_GT(m.volume.size(), 6u * parallel_grain);
    const CoarseSpacing spacing{2.0, 0.5};
    const int before = num_threads();
    set_num_threads(1);
    const CoarseWants one = coarse_wants(3, m.points, m.boundary.nodes, m.volume, spacing);
    const std::vector<NodeId> coarse_one = select_coarse_points(3, m.points, m.boundary.nodes, m.volume, spacing);
    ASSERT_GT(coarse_one.size(), 50u);
    for (int threads : {2, 3, 7}) {
        set_num_threads(threads);
        EXPECT_EQ(coarse_wants(3, m.points, m.boundary.nodes, m.volume, spacing).want, one.want) << threads;
        EXPECT_EQ(select_coarse_points(3, m.points, m.boundary.nodes, m.volume, spacing), coarse_one) << threads;
    }
    set_num_threads(before);
}
