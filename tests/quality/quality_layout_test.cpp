// The quality pass over a layout gives every cell its own
// cell_shape_quality (and cell_orientation) to the bit: meshes of simplices
// in a shuffled numbering with cells of both orientations, inverted and
// collapsed cells, NaN and huge coordinates, other cell types beside them,
// any thread count.
#include "dgwarp/quality/quality_layout.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <limits>
#include <cmath>
#include <cstring>
#include <numeric>
#include <random>

#include "dgwarp/core/parallel_for.hpp"
#include "dgwarp/quality/cell_quality.hpp"
#include "dgwarp/quality/mesh_quality.hpp"
#include "dgwarp/quality/simplex_kernel.hpp"

using namespace dgwarp;

namespace {

// n^dim grid squares (cubes) on [0, 1]^dim, split into 2 triangles (6
// tetrahedra) each, the nodes jittered and numbered in a random order, every
// seventh simplex written with two nodes swapped (the other orientation);
// `extra` hexahedra (3D) or quadrilaterals (2D) on the grid's first cells.
Mesh grid_mesh(int dim, int n, int extra, unsigned seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> jitter(-0.2 / n, 0.2 / n);
    const int nz = dim == 3 ? n : 0;
    const auto index = [&](int i, int j, int k) { return (k * (n + 1) + j) * (n + 1) + i; };
    const int count = (n + 1) * (n + 1) * (nz + 1);
    std::vector<NodeId> number(static_cast<std::size_t>(count));
    std::iota(number.begin(), number.end(), 0);
    std::shuffle(number.begin(), number.end(), rng);
    Mesh m;
    m.dim = dim;
    m.points.resize(static_cast<std::size_t>(count * dim));
    for (int k = 0; k <= nz; ++k)
        for (int j = 0; j <= n; ++j)
            for (int i = 0; i <= n; ++i) {
                const auto id = static_cast<std::size_t>(number[static_cast<std::size_t>(index(i, j, k))]);
                const int c[3] = {i, j, k};
                for (int d = 0; d < dim; ++d)
                    m.points[id * dim + d] =
                        static_cast<double>(c[d]) / n + (c[d] > 0 && c[d] < n ? jitter(rng) : 0.0);
            }
    const auto node = [&](int i, int j, int k) { return number[static_cast<std::size_t>(index(i, j, k))]; };
    std::size_t written = 0;
    const auto add = [&](CellType type, std::vector<NodeId> nodes) {
        if (nodes.size() <= 4 && ++written % 7 == 0) std::swap(nodes[0], nodes[1]);
        m.cells.push_back(type, nodes);
    };
    int extras = 0;
    for (int k = 0; k < std::max(nz, 1); ++k)
        for (int j = 0; j < n; ++j)
            for (int i = 0; i < n; ++i) {
                if (dim == 2) {
                    const NodeId a = node(i, j, 0), b = node(i + 1, j, 0), c = node(i + 1, j + 1, 0),
                                 d = node(i, j + 1, 0);
                    if (extras < extra) {
                        ++extras;
                        m.cells.push_back(CellType::quadrilateral, std::vector<NodeId>{a, b, c, d});
                        continue;
                    }
                    add(CellType::triangle, {a, b, c});
                    add(CellType::triangle, {a, c, d});
                    continue;
                }
                NodeId v[8];
                for (int q = 0; q < 8; ++q) v[q] = node(i + (q & 1), j + ((q >> 1) & 1), k + (q >> 2));
                if (extras < extra) {
                    ++extras;
                    m.cells.push_back(CellType::hexahedron,
                                      std::vector<NodeId>{v[0], v[1], v[3], v[2], v[4], v[5], v[7], v[6]});
                    continue;
                }
                // Six tetrahedra around the diagonal v0-v7.
                const int ring[6] = {1, 3, 2, 6, 4, 5};
                for (int t = 0; t < 6; ++t) add(CellType::tetrahedron, {v[0], v[ring[t]], v[ring[(t + 1) % 6]], v[7]});
            }
    return m;
}

// `points` moved at random by up to `amount` (inverting cells where it is
// large), one node at the position of a neighbour (collapsed cells) and,
// when asked, one node's coordinate NaN.
std::vector<double> shaken(const Mesh& m, double amount, bool nan, unsigned seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> u(-amount, amount);
    std::vector<double> p = m.points;
    for (double& x : p) x += u(rng);
    const auto nodes = m.cells.nodes_of(m.cells.size() / 2);
    const auto d = static_cast<std::size_t>(m.dim);
    for (std::size_t k = 0; k < d; ++k)
        p[static_cast<std::size_t>(nodes[0]) * d + k] = p[static_cast<std::size_t>(nodes[1]) * d + k];
    if (nan) p[static_cast<std::size_t>(m.cells.nodes_of(3)[2]) * d] = std::nan("");
    return p;
}

void expect_same_bits(const std::vector<double>& a, const std::vector<double>& b, const std::string& what) {
    ASSERT_EQ(a.size(), b.size()) << what;
    for (std::size_t i = 0; i < a.size(); ++i)
        ASSERT_EQ(std::memcmp(&a[i], &b[i], sizeof(double)), 0) << what << ": cell " << i << ": " << a[i] << " vs " << b[i];
}

}  // namespace

TEST(QualityLayout, EveryCellIsItsOwnCellShapeQualityToTheBit) {
    for (int dim : {2, 3}) {
        // 3D: 16^3 cubes, 24,546 tetrahedra (two blocks of the pass, a part block of the kernel) and 30 hexahedra.
        const Mesh m = grid_mesh(dim, dim == 3 ? 16 : 120, 30, 7u + static_cast<unsigned>(dim));
        const QualityLayout layout = make_quality_layout(m);
        ASSERT_TRUE(layout.fits(m));
        EXPECT_EQ(std::count_if(m.cells.types.begin(), m.cells.types.end(),
                                [](CellType t) { return t != CellType::tetrahedron && t != CellType::triangle; }),
                  30);
        const std::vector<std::int8_t> own = cell_orientations(m);
        const std::vector<std::int8_t> by_layout = cell_orientations(layout, m);
        EXPECT_EQ(by_layout, own) << dim << "D";
        EXPECT_GT(std::count(own.begin(), own.end(), -1), 0);  // both orientations in the mesh
        const std::vector<std::int8_t> orientation = dominant_orientations(m, own);
        for (double amount : {0.0, 0.02, 0.3}) {
            for (bool nan : {false, true}) {
                const std::vector<double> p = amount == 0 && !nan ? m.points : shaken(m, amount, nan, 11);
                const std::string what = std::to_string(dim) + "D, moved by " + std::to_string(amount) +
                                         (nan ? ", a NaN coordinate" : "");
                const std::vector<double> expected = cell_qualities(m, p, orientation);
                expect_same_bits(cell_qualities(layout, m, p, orientation), expected, what);
                if (amount == 0.3) {
                    EXPECT_GT(std::count_if(expected.begin(), expected.end(), [](double q) { return q < 0; }), 0)
                        << what;  // inverted cells among them
                }
            }
        }
        // Against the cells' own orientations (-1 for some), and on one thread.
        const std::vector<double> p = shaken(m, 0.02, false, 5);
        const int threads = num_threads();
        set_num_threads(1);
        const std::vector<double> serial = cell_qualities(layout, m, p, own);
        set_num_threads(threads);
        expect_same_bits(serial, cell_qualities(m, p, own), std::to_string(dim) + "D, own orientations, one thread");
        expect_same_bits(cell_qualities(layout, m, p, own), serial, std::to_string(dim) + "D, threads");
    }
}

TEST(QualityLayout, TheOriginalsOnePassGivesTheOrientationsAndQualitiesOfTheSeparatePasses) {
    for (int dim : {2, 3}) {
        for (double amount : {0.0, 0.02, 0.3}) {
            for (bool nan : {false, true}) {
                // Cells of both orientations (some flipped by the shake: -1 can then be the majority
                // of a type), collapsed and NaN cells, and hexahedra or quadrilaterals among them.
                Mesh m = grid_mesh(dim, dim == 3 ? 12 : 90, 25, 3u + static_cast<unsigned>(dim));
                if (amount > 0 || nan) m.points = shaken(m, amount, nan, 17);
                if (amount == 0.3) {
                    // Most simplices flipped: the majority against which they are judged is -1.
                    for (std::size_t c = 0; c < m.cells.size(); c += 4) {
                        auto* v = m.cells.nodes.data() + m.cells.offsets[c];
                        if (m.cells.types[c] != CellType::hexahedron && m.cells.types[c] != CellType::quadrilateral)
                            std::swap(v[0], v[1]);
                    }
                }
                const std::string what = std::to_string(dim) + "D, moved by " + std::to_string(amount) +
                                         (nan ? ", a NaN coordinate" : "");
                const QualityLayout layout = make_quality_layout(m);
                std::vector<std::int8_t> own, orientation;
                const std::vector<double> quality = original_qualities(layout, m, own, orientation);
                const std::vector<std::int8_t> expected_own = cell_orientations(m);
                const std::vector<std::int8_t> expected_orientation = dominant_orientations(m, expected_own);
                EXPECT_EQ(own, expected_own) << what;
                EXPECT_EQ(orientation, expected_orientation) << what;
                expect_same_bits(quality, cell_qualities(m, expected_orientation), what);
                // Another mesh's layout: the separate passes, the same values.
                const QualityLayout wrong = make_quality_layout(grid_mesh(dim, 4, 0, 1));
                std::vector<std::int8_t> own2, orientation2;
                expect_same_bits(original_qualities(wrong, m, own2, orientation2), quality, what + ", no layout");
                EXPECT_EQ(own2, own);
                EXPECT_EQ(orientation2, orientation);
            }
        }
    }
}

TEST(QualityLayout, HugeCoordinatesAndAnotherMeshsLayoutTakeTheCellsOneByOne) {
    const Mesh m = grid_mesh(3, 6, 2, 3);
    const QualityLayout layout = make_quality_layout(m);
    const std::vector<std::int8_t> orientation = dominant_orientations(m);
    // Beyond 2^400 cell_shape_quality scales a cell's points: the same values (and no overflow to NaN).
    std::vector<double> huge = m.points;
    for (double& x : huge) x = std::ldexp(x, 700);
    const std::vector<double> expected = cell_qualities(m, huge, orientation);
    EXPECT_TRUE(std::all_of(expected.begin(), expected.end(), [](double q) { return std::isfinite(q); }));
    expect_same_bits(cell_qualities(layout, m, huge, orientation), expected, "huge coordinates");
    // A layout of another mesh does not fit: the cells one by one, the same values.
    const Mesh other = grid_mesh(3, 5, 0, 3);
    const QualityLayout wrong = make_quality_layout(other);
    EXPECT_FALSE(wrong.fits(m));
    expect_same_bits(cell_qualities(wrong, m, m.points, orientation), cell_qualities(m, m.points, orientation),
                     "another mesh's layout");
    EXPECT_EQ(cell_orientations(wrong, m), cell_orientations(m));
    EXPECT_GT(layout_bytes(layout), 0u);
}

TEST(QualityLayout, TheLocalNumberingIsAPermutationAndItsInverse) {
    const Mesh m = grid_mesh(3, 5, 4, 9);
    const QualityLayout g = make_quality_layout(m);
    ASSERT_EQ(g.local_order.size(), m.num_points());
    ASSERT_EQ(g.local_id.size(), m.num_points());
    std::vector<int> seen(m.num_points(), 0);
    for (std::size_t k = 0; k < g.local_order.size(); ++k) {
        ++seen[static_cast<std::size_t>(g.local_order[k])];
        EXPECT_EQ(g.local_id[static_cast<std::size_t>(g.local_order[k])], static_cast<NodeId>(k));
    }
    EXPECT_TRUE(std::all_of(seen.begin(), seen.end(), [](int k) { return k == 1; }));
    EXPECT_EQ(layout_bytes(g), 2 * m.num_points() * sizeof(NodeId));
}

TEST(QualityLayout, TheInlinedCubeRootIsTheLibrarysToTheBit) {
    // Random positive normal numbers over the whole range, and each exponent's ends.
    std::mt19937_64 rng(42);
    std::vector<double> x;
    for (int i = 0; i < 200000; ++i) {
        const double m = 1.0 + static_cast<double>(rng() >> 12) * 0x1p-52;
        x.push_back(std::ldexp(m, static_cast<int>(rng() % 2046) - 1022));
    }
    for (int e = -1022; e <= 1023; ++e) {
        x.push_back(std::ldexp(1.0, e));
        x.push_back(std::ldexp(0x1.fffffffffffffp0, e));
    }
    for (double v : x)
        ASSERT_EQ(std::bit_cast<std::uint64_t>(quality_detail::glibc_cbrt_of_normal(v)),
                  std::bit_cast<std::uint64_t>(std::cbrt(v)))
            << v;
    // The kernel's cube roots, with the values it hands to std::cbrt itself.
    x.insert(x.end(), {0.0, -0.0, 0x1p-1074, 0x1p-1030, -8.0, std::numeric_limits<double>::infinity(), std::nan("")});
    std::vector<double> roots(x.size());
    quality_detail::cube_roots(x.data(), x.size(), roots.data());
    for (std::size_t i = 0; i < x.size(); ++i) {
        const double expected = std::cbrt(x[i]);
        ASSERT_EQ(std::memcmp(&roots[i], &expected, sizeof(double)), 0) << x[i];
    }
}
