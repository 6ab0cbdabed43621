#include "dgwarp/graph/delaunay_graph.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <numeric>
#include <random>

#include "dgwarp/core/error.hpp"
#include "dgwarp/core/parallel_for.hpp"
#include "support/random_points.hpp"

using namespace dgwarp;
using dgwarp::test::box_corners;
using dgwarp::test::random_points;

namespace {

// A point set: `boundary` first, then `volume`; returns node ids of each part.
struct PointSet {
    int dim;
    std::vector<double> points;
    std::vector<NodeId> boundary, volume;
};

PointSet make_set(int dim, const std::vector<double>& boundary, const std::vector<double>& volume) {
    PointSet s{dim, boundary, {}, {}};
    s.points.insert(s.points.end(), volume.begin(), volume.end());
    const auto nb = static_cast<NodeId>(boundary.size() / dim), nv = static_cast<NodeId>(volume.size() / dim);
    for (NodeId i = 0; i < nb; ++i) s.boundary.push_back(i);
    for (NodeId i = 0; i < nv; ++i) s.volume.push_back(nb + i);
    return s;
}

std::vector<double> concat(std::vector<double> a, const std::vector<double>& b) {
    a.insert(a.end(), b.begin(), b.end());
    return a;
}

double det3(const double* a, const double* b, const double* c) {
    return a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0]) + a[2] * (b[0] * c[1] - b[1] * c[0]);
}

// Barycentric coordinates of point x in the simplex with corner points p[0..dim], brute force.
std::vector<double> barycentric(int dim, const std::vector<const double*>& p, const double* x) {
    if (dim == 2) {
        auto area = [](const double* a, const double* b, const double* c) {
            return (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
        };
        const double total = area(p[0], p[1], p[2]);
        return {area(x, p[1], p[2]) / total, area(p[0], x, p[2]) / total, area(p[0], p[1], x) / total};
    }
    auto vol = [](const double* a, const double* b, const double* c, const double* d) {
        const double u[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]};
        const double v[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
        const double w[3] = {d[0] - a[0], d[1] - a[1], d[2] - a[2]};
        return det3(u, v, w);
    };
    const double total = vol(p[0], p[1], p[2], p[3]);
    return {vol(x, p[1], p[2], p[3]) / total, vol(p[0], x, p[2], p[3]) / total,
            vol(p[0], p[1], x, p[3]) / total, vol(p[0], p[1], p[2], x) / total};
}

// Corner points of graph simplex s.
std::vector<const double*> corners(const PointSet& s, const DelaunayGraph& g, std::size_t simplex) {
    std::vector<const double*> p;
    for (int k = 0; k <= s.dim; ++k) {
        const std::int32_t v = g.simplices[simplex * (s.dim + 1) + k];
        const NodeId node = s.boundary[g.vertex_nodes[g.vertex_offsets[v]]];
        p.push_back(s.points.data() + static_cast<std::size_t>(node) * s.dim);
    }
    return p;
}

double min_barycentric(const PointSet& s, const LocatedGraph& lg, std::size_t q) {
    const auto p = corners(s, lg.graph, static_cast<std::size_t>(lg.location.simplex[q]));
    const auto b = barycentric(s.dim, p, s.points.data() + static_cast<std::size_t>(s.volume[q]) * s.dim);
    return *std::min_element(b.begin(), b.end());
}

void expect_every_node_in_its_simplex(const PointSet& s, const LocatedGraph& lg) {
    ASSERT_EQ(lg.location.simplex.size(), s.volume.size());
    for (std::size_t q = 0; q < s.volume.size(); ++q) {
        ASSERT_GE(lg.location.simplex[q], 0);
        ASSERT_LT(static_cast<std::size_t>(lg.location.simplex[q]), lg.graph.num_simplices());
        EXPECT_GE(min_barycentric(s, lg, q), -1e-12) << "query " << q;
    }
}

// Brute-force checks of the graph: simplices positive, volumes sum to the hull's, empty circumspheres.
void expect_valid_delaunay(const PointSet& s, const DelaunayGraph& g, double hull_measure, double in_tolerance = 1e-12) {
    double total = 0;
    for (std::size_t t = 0; t < g.num_simplices(); ++t) {
        const auto p = corners(s, g, t);
        double m;
        if (s.dim == 2) {
            m = 0.5 * ((p[1][0] - p[0][0]) * (p[2][1] - p[0][1]) - (p[1][1] - p[0][1]) * (p[2][0] - p[0][0]));
        } else {
            const double u[3] = {p[1][0] - p[0][0], p[1][1] - p[0][1], p[1][2] - p[0][2]};
            const double v[3] = {p[2][0] - p[0][0], p[2][1] - p[0][1], p[2][2] - p[0][2]};
            const double w[3] = {p[3][0] - p[0][0], p[3][1] - p[0][1], p[3][2] - p[0][2]};
            m = det3(u, v, w) / 6;
        }
        EXPECT_GT(m, 0) << "simplex " << t << " is not positively oriented";
        total += m;
        // Empty circumsphere: no boundary point strictly inside (lifted-paraboloid test with a tolerance).
        for (NodeId b : s.boundary) {
            const double* x = s.points.data() + static_cast<std::size_t>(b) * s.dim;
            double rows[4][4];
            for (int k = 0; k <= s.dim; ++k) {
                double sq = 0;
                for (int d = 0; d < s.dim; ++d) {
                    rows[k][d] = p[k][d] - x[d];
                    sq += rows[k][d] * rows[k][d];
                }
                rows[k][s.dim] = sq;
            }
            double in;
            if (s.dim == 2) {
                in = det3(rows[0], rows[1], rows[2]);
            } else {
                in = 0;
                for (int c = 0; c < 4; ++c) {
                    double minor[3][3];
                    for (int r = 1; r < 4; ++r)
                        for (int cc = 0, j = 0; cc < 4; ++cc)
                            if (cc != c) minor[r - 1][j++] = rows[r][cc];
                    in += (c % 2 ? -1 : 1) * rows[0][c] * det3(minor[0], minor[1], minor[2]);
                }
                in = -in;  // orientation sign of the 4x4 insphere determinant
            }
            EXPECT_LE(in, in_tolerance) << "point " << b << " inside the circumsphere of simplex " << t;
        }
    }
    EXPECT_NEAR(total, hull_measure, 1e-12);
}

}  // namespace

TEST(GraphLocate, RandomPoints2dAgreeWithBruteForce) {
    const PointSet s = make_set(2, concat(box_corners(2), random_points(2, 60, 1)), random_points(2, 2000, 2));
    const LocatedGraph lg = build_located_graph(2, s.points, s.boundary, s.volume);
    EXPECT_EQ(lg.timings.triangulation_builds, 1);  // 2D: one build, on the original coordinates
    EXPECT_EQ(lg.graph.num_vertices(), 64u);
    EXPECT_EQ(lg.location.outside_count, 0);
    expect_valid_delaunay(s, lg.graph, 1.0);
    expect_every_node_in_its_simplex(s, lg);
}

TEST(GraphLocate, RandomPoints3dAgreeWithBruteForce) {
    const PointSet s = make_set(3, concat(box_corners(3), random_points(3, 60, 3)), random_points(3, 3000, 4));
    const LocatedGraph lg = build_located_graph(3, s.points, s.boundary, s.volume);
    EXPECT_EQ(lg.graph.num_vertices(), 68u);
    EXPECT_EQ(lg.location.outside_count, 0);
    expect_valid_delaunay(s, lg.graph, 1.0);
    expect_every_node_in_its_simplex(s, lg);
}

namespace {

// Sorted corner coordinates of every simplex: the graph as a set of point sets.
std::vector<std::array<std::array<double, 3>, 4>> simplex_point_sets(const PointSet& set, const DelaunayGraph& g) {
    std::vector<std::array<std::array<double, 3>, 4>> out;
    for (std::size_t t = 0; t < g.num_simplices(); ++t) {
        std::array<std::array<double, 3>, 4> simplex;
        const auto p = corners(set, g, t);
        for (int k = 0; k < 4; ++k) simplex[k] = {p[k][0], p[k][1], p[k][2]};
        std::sort(simplex.begin(), simplex.end());
        out.push_back(simplex);
    }
    std::sort(out.begin(), out.end());
    return out;
}

}  // namespace

TEST(GraphLocate, PlateAndLatticeBoundariesGiveAValidDelaunayGraph) {
    // Boundary points with ties everywhere: the unit cube's corners, a plate
    // of a 9x9 grid at z = 0.375 (exactly coplanar and cocircular), then also
    // a 5x5x5 lattice (exactly cospherical eights, coplanar rows). The graph
    // is built on perturbed coordinates (delaunay_graph.hpp); every simplex
    // must be positively oriented in the original ones (a simplex of four
    // coplanar points would have volume exactly 0 here: the coordinates are
    // binary fractions or the same quotients) and Delaunay up to the
    // perturbation's tolerance. Measured: the plate needs a second build (the
    // first makes flat simplices of plate points, whose corners then stay
    // put), the lattice the third, on the original coordinates.
    for (const bool lattice : {false, true}) {
        std::vector<double> boundary = box_corners(3), volume;
        for (int i = 0; i <= 8; ++i)
            for (int j = 0; j <= 8; ++j)
                for (double c : {0.25 + i / 16.0, 0.25 + j / 16.0, 0.375}) boundary.push_back(c);
        if (lattice)
            for (int i = 1; i <= 5; ++i)
                for (int j = 1; j <= 5; ++j)
                    for (int k = 1; k <= 5; ++k)
                        for (double c : {i / 6.0, j / 6.0, k / 6.0}) boundary.push_back(c);
        for (int i = 0; i < 6; ++i)
            for (int j = 0; j < 6; ++j)
                for (int k = 0; k < 6; ++k)
                    for (double c : {(i + 0.4) / 6.0, (j + 0.45) / 6.0, (k + 0.35) / 6.0}) volume.push_back(c);
        const PointSet s = make_set(3, boundary, volume);
        const LocatedGraph lg = build_located_graph(3, s.points, s.boundary, s.volume);
        EXPECT_EQ(lg.timings.triangulation_builds, lattice ? 3 : 2);
        EXPECT_EQ(lg.location.outside_count, 0);
        expect_valid_delaunay(s, lg.graph, 1.0, 1e-10);
        expect_every_node_in_its_simplex(s, lg);
        // The same points renumbered give the same graph (the perturbation follows coordinates, not ids).
        PointSet reversed = s;
        const std::size_t nb = s.boundary.size();
        for (std::size_t k = 0; k < nb; ++k)
            std::copy_n(s.points.data() + 3 * (nb - 1 - k), 3, reversed.points.data() + 3 * k);
        const LocatedGraph again = build_located_graph(3, reversed.points, reversed.boundary, reversed.volume);
        EXPECT_EQ(simplex_point_sets(s, lg.graph), simplex_point_sets(reversed, again.graph));
    }
}

TEST(GraphLocate, CospherialBoundaryNeedsOneBuild) {
    // Points on a sphere (cospherical up to round-off: nearly every in-sphere
    // test a near-tie) inside a box: one build on perturbed coordinates, valid.
    std::vector<double> boundary;
    for (double c : box_corners(3)) boundary.push_back(4 * c - 2);
    std::mt19937 rng(7);
    std::normal_distribution<double> gauss;
    for (int i = 0; i < 400; ++i) {
        double x[3] = {gauss(rng), gauss(rng), gauss(rng)};
        const double r = std::sqrt(x[0] * x[0] + x[1] * x[1] + x[2] * x[2]);
        for (double c : x) boundary.push_back(c / r);
    }
    const std::vector<double> unit = random_points(3, 500, 8);
    std::vector<double> volume;
    for (double c : unit) volume.push_back(4 * c - 2);
    const PointSet s = make_set(3, boundary, volume);
    const LocatedGraph lg = build_located_graph(3, s.points, s.boundary, s.volume);
    EXPECT_EQ(lg.timings.triangulation_builds, 1);
    expect_valid_delaunay(s, lg.graph, 64.0, 1e-10);
    expect_every_node_in_its_simplex(s, lg);
}

TEST(GraphLocate, NodesOnVerticesEdgesAndFacesAreInsideOrOn) {
    // Boundary: a regular grid (many cospherical points: degenerate Delaunay); queries
    // on grid points, grid lines and cell centres, all on simplex boundaries of some kind.
    for (int dim : {2, 3}) {
        std::vector<double> grid, queries;
        const int n = 4;
        for (int i = 0; i < (dim == 2 ? n * n : n * n * n); ++i) {
            const int c[3] = {i % n, (i / n) % n, i / (n * n)};
            for (int d = 0; d < dim; ++d) grid.push_back(c[d]);
            for (int d = 0; d < dim; ++d) queries.push_back(c[d]);        // on a vertex
            for (int d = 0; d < dim; ++d) queries.push_back(c[d] * 0.75 + (d == 0 ? 0.5 : 0));  // on lines / inside
            for (int d = 0; d < dim; ++d) queries.push_back(c[d] * 0.75 + 0.5);  // centres
        }
        const PointSet s = make_set(dim, grid, queries);
        const LocatedGraph lg = build_located_graph(dim, s.points, s.boundary, s.volume);
        EXPECT_EQ(lg.location.outside_count, 0) << dim << "D";
        expect_every_node_in_its_simplex(s, lg);
    }
}

TEST(GraphLocate, MortonAndGivenOrderAgreeAndThreadCountDoesNotMatter) {
    for (int dim : {2, 3}) {
        // More queries than one location block, so blocks run in parallel.
        const PointSet s = make_set(dim, concat(box_corners(dim), random_points(dim, 300, 5)),
                                    random_points(dim, 20000, 6));
        const int threads = num_threads();
        set_num_threads(1);
        const LocatedGraph one = build_located_graph(dim, s.points, s.boundary, s.volume);
        set_num_threads(2);
        const LocatedGraph two = build_located_graph(dim, s.points, s.boundary, s.volume);
        const LocatedGraph given = build_located_graph(dim, s.points, s.boundary, s.volume, {LocateOrder::given});
        set_num_threads(threads);
        EXPECT_TRUE(one.timings.spatially_sorted);  // random points: not coherent
        EXPECT_FALSE(given.timings.spatially_sorted);
        EXPECT_EQ(one.graph.simplices, two.graph.simplices);
        EXPECT_EQ(one.location.simplex, two.location.simplex);
        // Random points are in general position: each lies in exactly one simplex.
        EXPECT_EQ(one.location.simplex, given.location.simplex);
        expect_every_node_in_its_simplex(s, one);
    }
}

TEST(GraphLocate, WorkBesideTheLocationSeesTheWholeGraphOnceAndItsErrorIsRethrown) {
    for (int dim : {2, 3}) {
        const PointSet s = make_set(dim, concat(box_corners(dim), random_points(dim, 300, 5)),
                                    random_points(dim, 20000, 6));
        const int threads = num_threads();
        for (int t : {1, 2, 3}) {
            set_num_threads(t);
            const LocatedGraph plain = build_located_graph(dim, s.points, s.boundary, s.volume);
            GraphOptions options;
            int calls = 0;
            DelaunayGraph seen;
            options.beside_locate = [&](const DelaunayGraph& g) {
                ++calls;
                seen = g;
            };
            const LocatedGraph with = build_located_graph(dim, s.points, s.boundary, s.volume, options);
            EXPECT_EQ(calls, 1);
            EXPECT_EQ(seen.dim, dim);
            EXPECT_EQ(seen.simplices, plain.graph.simplices);
            EXPECT_EQ(seen.vertex_offsets, plain.graph.vertex_offsets);
            EXPECT_EQ(seen.vertex_nodes, plain.graph.vertex_nodes);
            EXPECT_EQ(with.graph.simplices, plain.graph.simplices);  // handed back after the call
            EXPECT_EQ(with.location.simplex, plain.location.simplex);
            options.beside_locate = [](const DelaunayGraph&) { throw MeshError("beside"); };
            try {
                build_located_graph(dim, s.points, s.boundary, s.volume, options);
                ADD_FAILURE() << "no error";
            } catch (const MeshError& e) {
                EXPECT_STREQ(e.what(), "beside");
            }
        }
        set_num_threads(threads);
    }
}

TEST(GraphLocate, NodesOnFacesAndOutsideTheHullGetTheSameSimplexWhateverTheOtherQueries) {
    // A grid boundary (degenerate Delaunay: many choices of simplices) with
    // queries on its vertices, grid lines and cell centres, and queries
    // outside the hull. A walk's result depends on the previous query's
    // simplex; the location must not (a process of an MPI run locates only
    // its own nodes: dgwarp/mpi).
    for (int dim : {2, 3}) {
        std::vector<double> grid, queries;
        const int n = 4;
        for (int i = 0; i < (dim == 2 ? n * n : n * n * n); ++i) {
            const int c[3] = {i % n, (i / n) % n, i / (n * n)};
            for (int d = 0; d < dim; ++d) grid.push_back(c[d] / 3.0);
            for (int d = 0; d < dim; ++d) queries.push_back(c[d] / 3.0);
            for (int d = 0; d < dim; ++d) queries.push_back((c[d] * 0.75 + (d == 0 ? 0.5 : 0)) / 3.0);
            for (int d = 0; d < dim; ++d) queries.push_back((c[d] * 0.75 + 0.5) / 3.0);
        }
        const std::vector<double> outside = random_points(dim, 60, 31, 1.2, 2.5);
        for (std::size_t i = 0; i < outside.size(); ++i) queries.push_back(i % 4 == 1 ? -outside[i] + 1 : outside[i]);
        const PointSet s = make_set(dim, grid, queries);
        const LocatedGraph all = build_located_graph(dim, s.points, s.boundary, s.volume, {LocateOrder::given});
        std::vector<NodeId> reversed(s.volume.rbegin(), s.volume.rend()), odd;
        for (std::size_t q = 1; q < s.volume.size(); q += 2) odd.push_back(s.volume[q]);
        const LocatedGraph back = build_located_graph(dim, s.points, s.boundary, reversed, {LocateOrder::given});
        const LocatedGraph morton = build_located_graph(dim, s.points, s.boundary, odd, {LocateOrder::morton});
        ASSERT_EQ(all.graph.simplices, back.graph.simplices);
        ASSERT_EQ(all.graph.simplices, morton.graph.simplices);
        EXPECT_EQ(all.location.outside_count, 60);
        for (std::size_t q = 0; q < s.volume.size(); ++q) {
            EXPECT_EQ(all.location.simplex[q], back.location.simplex[s.volume.size() - 1 - q]) << dim << "D query " << q;
            if (q % 2 == 1) {
                EXPECT_EQ(all.location.simplex[q], morton.location.simplex[q / 2]) << dim << "D query " << q;
            }
        }
        expect_every_node_in_its_simplex(PointSet{dim, s.points, s.boundary, std::vector<NodeId>(s.volume.begin(), s.volume.end() - 60)},
                                         LocatedGraph{all.graph, {std::vector<std::int32_t>(all.location.simplex.begin(), all.location.simplex.end() - 60), 0}, {}});
        // An outside node gets a simplex with a hull facet it sees: a negative
        // barycentric coordinate whose opposite facet lies on a face of the box.
        for (std::size_t q = s.volume.size() - 60; q < s.volume.size(); ++q) {
            const auto p = corners(s, all.graph, static_cast<std::size_t>(all.location.simplex[q]));
            const auto e = barycentric(dim, p, s.points.data() + static_cast<std::size_t>(s.volume[q]) * dim);
            bool sees_hull_facet = false;
            for (int k = 0; k <= dim; ++k) {
                if (e[k] >= 0) continue;
                for (int d = 0; d < dim; ++d)
                    for (double side : {0.0, 1.0}) {
                        int on = 0;
                        for (int j = 0; j <= dim; ++j) on += j != k && p[j][d] == side;
                        sees_hull_facet |= on == dim;
                    }
            }
            EXPECT_TRUE(sees_hull_facet) << dim << "D outside query " << q;
        }
    }
}

TEST(GraphLocate, DuplicateBoundaryPointsShareOneVertexAndKeepTheirIds) {
    for (int dim : {2, 3}) {
        std::vector<double> b = concat(box_corners(dim), random_points(dim, 20, 7));
        // Boundary indices 28.. repeat the points of indices 3, 10 and 10 again.
        const int nb = static_cast<int>(b.size()) / dim;
        for (int src : {3, 10, 10})
            for (int d = 0; d < dim; ++d) b.push_back(b[src * dim + d]);
        const PointSet s = make_set(dim, b, random_points(dim, 500, 8));
        const LocatedGraph lg = build_located_graph(dim, s.points, s.boundary, s.volume);
        const DelaunayGraph& g = lg.graph;
        ASSERT_EQ(g.num_vertices(), static_cast<std::size_t>(nb));
        EXPECT_EQ(g.vertex_nodes.size(), static_cast<std::size_t>(nb + 3));
        // Vertices are numbered by first boundary index, so vertex 3 holds {3, nb} and vertex 10 {10, nb+1, nb+2}.
        auto members = [&](int v) {
            return std::vector<std::int32_t>(g.vertex_nodes.begin() + g.vertex_offsets[v],
                                             g.vertex_nodes.begin() + g.vertex_offsets[v + 1]);
        };
        EXPECT_EQ(members(3), (std::vector<std::int32_t>{3, nb}));
        EXPECT_EQ(members(10), (std::vector<std::int32_t>{10, nb + 1, nb + 2}));
        EXPECT_EQ(members(4), (std::vector<std::int32_t>{4}));
        expect_every_node_in_its_simplex(s, lg);
    }
}

TEST(GraphLocate, OutsideHullNodesAreCountedAndGetAHullSimplex) {
    for (int dim : {2, 3}) {
        // Boundary: a box [0,1]^dim. Queries: 200 inside, and 37 outside at distance >= 0.5.
        const std::vector<double> inside = random_points(dim, 200, 9, 0.01, 0.99);
        std::vector<double> outside = random_points(dim, 37, 10, 1.5, 3.0);
        for (std::size_t i = 0; i < outside.size(); i += 3) outside[i] = -outside[i];  // several sides
        const PointSet s = make_set(dim, concat(box_corners(dim), random_points(dim, 30, 11, 0.1, 0.9)),
                                    concat(inside, outside));
        const LocatedGraph lg = build_located_graph(dim, s.points, s.boundary, s.volume);
        EXPECT_EQ(lg.location.outside_count, 37) << dim << "D";
        expect_valid_delaunay(s, lg.graph, 1.0);
        // Inside nodes are in their simplex; outside nodes get a finite simplex having
        // a facet on the hull (dim of its corners on one face of the box).
        for (std::size_t q = 0; q < s.volume.size(); ++q) {
            const auto simplex = static_cast<std::size_t>(lg.location.simplex[q]);
            ASSERT_LT(simplex, lg.graph.num_simplices());
            if (q < 200) {
                EXPECT_GE(min_barycentric(s, lg, q), -1e-12);
                continue;
            }
            const auto p = corners(s, lg.graph, simplex);
            bool on_hull = false;
            for (int d = 0; d < dim; ++d)
                for (double side : {0.0, 1.0})
                    on_hull |= std::count_if(p.begin(), p.end(), [&](const double* c) { return c[d] == side; }) >= dim;
            EXPECT_TRUE(on_hull) << "outside query " << q;
        }
    }
}

TEST(GraphLocate, DegenerateBoundariesAreRefused) {
    auto expect_mesh_error = [](int dim, const std::vector<double>& pts, const std::string& words) {
        std::vector<NodeId> b(pts.size() / dim);
        std::iota(b.begin(), b.end(), 0);
        try {
            build_located_graph(dim, pts, b, {});
            ADD_FAILURE() << "no error for " << words;
        } catch (const MeshError& e) {
            EXPECT_NE(std::string(e.what()).find(words), std::string::npos) << e.what();
        }
    };
    expect_mesh_error(2, {0, 0, 1, 1}, "at least 3 distinct");
    expect_mesh_error(2, {0, 0, 1, 1, 1, 1, 0, 0}, "at least 3 distinct");  // 4 nodes, 2 points
    expect_mesh_error(2, {0, 0, 1, 1, 2, 2, 3, 3, 0.5, 0.5}, "collinear");
    expect_mesh_error(3, {0, 0, 0, 1, 0, 0, 0, 1, 0}, "at least 4 distinct");
    expect_mesh_error(3, {0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0, 0.3, 0.7, 0}, "coplanar");
    expect_mesh_error(3, {0, 0, 0, 1, 1, 1, 2, 2, 2, 3, 3, 3}, "collinear");
    // Node ids out of range and non-finite coordinates.
    const std::vector<double> tri = {0, 0, 1, 0, 0, 1};
    const std::vector<NodeId> bad = {0, 1, 5};
    EXPECT_THROW(build_located_graph(2, tri, bad, {}), MeshError);
    const std::vector<double> nan_pts = {0, 0, 1, 0, 0, std::nan("")};
    const std::vector<NodeId> ok = {0, 1, 2};
    EXPECT_THROW(build_located_graph(2, nan_pts, ok, {}), MeshError);
}

TEST(GraphLocate, GridOrderIsCoherentAndARandomOrderIsNot) {
    for (int dim : {2, 3}) {
        std::vector<double> grid;
        const int n = dim == 2 ? 60 : 16;
        for (int i = 0; i < (dim == 2 ? n * n : n * n * n); ++i)
            for (int d = 0; d < dim; ++d) grid.push_back((i / (d == 0 ? 1 : d == 1 ? n : n * n)) % n);
        std::vector<NodeId> ids(grid.size() / dim);
        std::iota(ids.begin(), ids.end(), 0);
        EXPECT_TRUE(is_coherent_order(dim, grid, ids)) << dim << "D";
        std::mt19937 rng(3);
        std::shuffle(ids.begin(), ids.end(), rng);
        EXPECT_FALSE(is_coherent_order(dim, grid, ids)) << dim << "D";
    }
}
