#include "dgwarp/quality/mesh_quality.hpp"

#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>

#include "dgwarp/core/ordered_sum.hpp"
#include "dgwarp/core/parallel_for.hpp"
#include "dgwarp/quality/cell_quality.hpp"

using namespace dgwarp;

namespace {

// Appends a cell whose nodes are new points `xy` (dim values each).
void add_cell(Mesh& m, CellType type, std::vector<double> xy) {
    std::vector<NodeId> ids;
    for (std::size_t i = 0; i < xy.size(); i += static_cast<std::size_t>(m.dim)) {
        ids.push_back(static_cast<NodeId>(m.num_points()));
        m.points.insert(m.points.end(), xy.begin() + static_cast<std::ptrdiff_t>(i),
                        xy.begin() + static_cast<std::ptrdiff_t>(i) + m.dim);
    }
    m.cells.push_back(type, ids);
}

// Unit square (1), trapezoid (32/39), 30-60-90 triangle (0.75) and a clockwise
// right isosceles triangle (-√3/2 against the counter-clockwise majority).
Mesh mixed_2d_mesh() {
    Mesh m;
    m.dim = 2;
    add_cell(m, CellType::quadrilateral, {0, 0, 1, 0, 1, 1, 0, 1});
    add_cell(m, CellType::quadrilateral, {1, 0, 3, 0, 2.5, 1, 1.5, 1});
    add_cell(m, CellType::triangle, {0, 1, std::sqrt(3.0), 1, 0, 2});
    add_cell(m, CellType::triangle, {3, 0, 4, 1, 4, 0});
    add_cell(m, CellType::triangle, {5, 0, 6, 0, 5, 1});
    return m;
}

Mesh mirrored(Mesh m) {
    for (std::size_t i = 0; i < m.points.size(); i += static_cast<std::size_t>(m.dim)) m.points[i] = -m.points[i];
    return m;
}

// A structured nx × ny × nz hexahedral grid with randomly moved nodes.
Mesh perturbed_hex_grid(int nx, int ny, int nz, std::uint32_t seed) {
    Mesh m;
    m.dim = 3;
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> u(-0.2, 0.2);
    for (int k = 0; k <= nz; ++k)
        for (int j = 0; j <= ny; ++j)
            for (int i = 0; i <= nx; ++i) m.points.insert(m.points.end(), {i + u(rng), j + u(rng), k + u(rng)});
    auto id = [&](int i, int j, int k) { return static_cast<NodeId>((k * (ny + 1) + j) * (nx + 1) + i); };
    for (int k = 0; k < nz; ++k)
        for (int j = 0; j < ny; ++j)
            for (int i = 0; i < nx; ++i) {
                const NodeId h[] = {id(i, j, k),     id(i + 1, j, k),     id(i + 1, j + 1, k),     id(i, j + 1, k),
                                    id(i, j, k + 1), id(i + 1, j, k + 1), id(i + 1, j + 1, k + 1), id(i, j + 1, k + 1)};
                m.cells.push_back(CellType::hexahedron, h);
            }
    return m;
}

}  // namespace

TEST(QualityDriver, MixedMeshHandComputedSummary) {
    const Mesh m = mixed_2d_mesh();
    const auto orientation = dominant_orientations(m);
    EXPECT_EQ(orientation, (std::vector<std::int8_t>{1, 1, 1, 1, 1}));
    const auto quality = cell_qualities(m, orientation);
    const double s3 = std::sqrt(3.0);
    const double expected[] = {1.0, 32.0 / 39.0, 0.75, -s3 / 2, s3 / 2};
    ASSERT_EQ(quality.size(), 5u);
    for (int i = 0; i < 5; ++i) EXPECT_NEAR(quality[i], expected[i], 1e-12) << "cell " << i;

    const QualitySummary s = summarize_quality(quality);
    EXPECT_EQ(s.cells, 5);
    EXPECT_NEAR(s.min, -s3 / 2, 1e-12);
    EXPECT_EQ(s.worst_cell, 3);
    EXPECT_NEAR(s.mean, (1.0 + 32.0 / 39.0 + 0.75) / 5, 1e-12);
    EXPECT_EQ(s.inverted, 1);
    ASSERT_EQ(s.histogram.counts.size(), 11u);
    ASSERT_EQ(s.histogram.edges.size(), 12u);
    EXPECT_EQ(s.histogram.edges[0], -std::numeric_limits<double>::infinity());
    EXPECT_EQ(s.histogram.edges[1], 0.0);
    EXPECT_EQ(s.histogram.edges[11], 1.0);
    //                      (-inf,0] .1 .2 .3 .4 .5 .6 .7 .8 .9  1
    const std::vector<std::int64_t> counts{1, 0, 0, 0, 0, 0, 0, 0, 1, 2, 1};
    EXPECT_EQ(s.histogram.counts, counts);
}

TEST(QualityDriver, MeshWrittenClockwiseIsNotInverted) {
    const Mesh m = mirrored(mixed_2d_mesh());
    const auto orientation = dominant_orientations(m);
    EXPECT_EQ(orientation, (std::vector<std::int8_t>{-1, -1, -1, -1, -1}));
    const auto original = cell_qualities(mixed_2d_mesh(), dominant_orientations(mixed_2d_mesh()));
    const auto quality = cell_qualities(m, orientation);
    for (std::size_t i = 0; i < quality.size(); ++i) EXPECT_NEAR(quality[i], original[i], 1e-14);
    EXPECT_EQ(summarize_quality(quality).inverted, 1);
}

TEST(QualityDriver, DominantOrientationIsPerCellTypeWithTiesPositive) {
    Mesh m;
    m.dim = 2;
    add_cell(m, CellType::triangle, {0, 0, 1, 0, 0, 1});      // counter-clockwise
    add_cell(m, CellType::triangle, {0, 0, 0, 1, 1, 0});      // clockwise: a tie
    add_cell(m, CellType::quadrilateral, {0, 0, 0, 1, 1, 1, 1, 0});  // clockwise quads
    add_cell(m, CellType::quadrilateral, {2, 0, 2, 1, 3, 1, 3, 0});
    add_cell(m, CellType::quadrilateral, {4, 0, 5, 0, 5, 1, 4, 1});  // one counter-clockwise
    EXPECT_EQ(cell_orientations(m), (std::vector<std::int8_t>{1, -1, -1, -1, 1}));
    EXPECT_EQ(dominant_orientations(m), (std::vector<std::int8_t>{1, 1, -1, -1, -1}));
    const auto quality = cell_qualities(m, dominant_orientations(m));
    EXPECT_GT(quality[0], 0);
    EXPECT_LE(quality[1], 0);
    EXPECT_NEAR(quality[2], 1.0, 1e-12);
    EXPECT_NEAR(quality[3], 1.0, 1e-12);
    EXPECT_LE(quality[4], 0);
}

TEST(QualityDriver, ReferenceOrientationsJudgeADeformedMesh) {
    const Mesh reference = perturbed_hex_grid(3, 3, 3, 1);
    const auto orientation = cell_orientations(reference);
    Mesh deformed = reference;
    // push the first cell's node 4 below its bottom face
    const NodeId n4 = deformed.cells.nodes_of(0)[4];
    deformed.points[3 * static_cast<std::size_t>(n4) + 2] = -1.0;
    const auto quality = cell_qualities(deformed, orientation);
    EXPECT_LE(quality[0], 0);
    const QualitySummary s = summarize_quality(quality);
    EXPECT_EQ(s.worst_cell, 0);
    EXPECT_GE(s.inverted, 1);
}

TEST(QualityDriver, OtherPointsGiveWhatACopyOfTheMeshWithThemGives) {
    const Mesh reference = perturbed_hex_grid(3, 3, 3, 2);
    const auto orientation = cell_orientations(reference);
    Mesh deformed = reference;
    for (std::size_t i = 0; i < deformed.points.size(); ++i) deformed.points[i] += 0.05 * std::sin(3.0 * i);
    const NodeId n4 = deformed.cells.nodes_of(0)[4];
    deformed.points[3 * static_cast<std::size_t>(n4) + 2] = -1.0;  // one inverted cell among them
    const auto from_copy = cell_qualities(deformed, orientation);
    const auto from_points = cell_qualities(reference, deformed.points, orientation);
    EXPECT_EQ(from_points, from_copy);  // bit for bit
    EXPECT_LE(from_points[0], 0);
    EXPECT_EQ(cell_qualities(reference, reference.points, orientation), cell_qualities(reference, orientation));
}

TEST(QualityDriver, ThreadCountDoesNotChangeTheResult) {
    const Mesh m = perturbed_hex_grid(24, 20, 16, 9);
    const int threads = num_threads();
    set_num_threads(1);
    const auto one = cell_qualities(m, cell_orientations(m));
    set_num_threads(2);
    const auto two = cell_qualities(m, cell_orientations(m));
    set_num_threads(threads);
    ASSERT_EQ(one.size(), m.cells.size());
    EXPECT_EQ(one, two);  // bit-identical
    const QualitySummary a = summarize_quality(one), b = summarize_quality(two);
    EXPECT_EQ(a.mean, b.mean);
    EXPECT_EQ(a.min, b.min);
    EXPECT_EQ(a.histogram.counts, b.histogram.counts);
}

TEST(QualityDriver, HistogramBinEdgesAreInclusiveAboveAndRoundOffGoesToTheLastBin) {
    const std::vector<double> q{0.0, -0.5, 0.1, 0.1000001, 0.3, 1.0, 1.0 + 1e-15, 0.95};
    const QualitySummary s = summarize_quality(q);
    const std::vector<std::int64_t> counts{2, 1, 1, 1, 0, 0, 0, 0, 0, 0, 3};
    EXPECT_EQ(s.histogram.counts, counts);
    EXPECT_EQ(s.inverted, 2);
    EXPECT_EQ(s.worst_cell, 1);
    EXPECT_EQ(s.min, -0.5);
}

TEST(QualityDriver, HistogramBinsAreTheFirstEdgeScansOnEveryEdgeAndBetween) {
    // Every bin edge, its neighbours one ulp away, values between, beyond 1 and inf, NaN:
    // the bin is the first b >= 1 with q <= edges[b + 1] (the last bin above), by brute force.
    std::vector<double> q;
    const std::vector<double> edges = summarize_quality(std::vector<double>{0.5}).histogram.edges;
    for (std::size_t b = 1; b < edges.size(); ++b)
        for (double v : {edges[b], std::nextafter(edges[b], 0.0), std::nextafter(edges[b], 2.0)}) q.push_back(v);
    std::mt19937 rng(5);
    std::uniform_real_distribution<double> u(-0.1, 1.1);
    for (int k = 0; k < 2000; ++k) q.push_back(u(rng));
    q.insert(q.end(), {1e-300, 5e-324, 1.0 + 1e-12, std::numeric_limits<double>::infinity(),
                       std::numeric_limits<double>::quiet_NaN()});
    std::vector<std::int64_t> expected(edges.size() - 1, 0);
    for (double v : q) {
        std::size_t bin = 0;
        if (v > 0) {
            bin = 1;
            while (bin < expected.size() - 1 && v > edges[bin + 1]) ++bin;
        }
        ++expected[bin];
    }
    EXPECT_EQ(summarize_quality(q).histogram.counts, expected);
}

TEST(QualityDriver, EveryCellIsItsOwnCellShapeQualityWhateverItsType) {
    // Tetrahedra (measured by the driver's own loop), mirrored ones and other types alike.
    const Mesh grid = perturbed_hex_grid(6, 5, 4, 3);
    Mesh m = grid;
    for (std::size_t c = 0; c < grid.cells.size(); c += 2) {
        const auto n = grid.cells.nodes_of(c);
        const NodeId t1[] = {n[0], n[1], n[3], n[4]}, t2[] = {n[1], n[0], n[3], n[4]};  // t2 mirrored
        m.cells.push_back(CellType::tetrahedron, t1);
        m.cells.push_back(CellType::tetrahedron, t2);
    }
    const std::vector<std::int8_t> own = cell_orientations(m), majority = dominant_orientations(m);
    for (const auto* orientation : {&own, &majority}) {
        const std::vector<double> q = cell_qualities(m, *orientation);
        for (std::size_t c = 0; c < m.cells.size(); ++c) {
            std::vector<double> coords;
            for (NodeId v : m.cells.nodes_of(c))
                for (int d = 0; d < 3; ++d) coords.push_back(m.points[3 * static_cast<std::size_t>(v) + d]);
            ASSERT_EQ(q[c], cell_shape_quality(m.cells.types[c], coords, 3, (*orientation)[c])) << c;  // bit for bit
        }
    }
}

TEST(QualityDriver, EmptySummary) {
    const QualitySummary s = summarize_quality({});
    EXPECT_EQ(s.cells, 0);
    EXPECT_EQ(s.worst_cell, -1);
    EXPECT_EQ(s.inverted, 0);
    EXPECT_EQ(s.histogram.counts, std::vector<std::int64_t>(11, 0));
    const RatioSummary r = summarize_ratios({});
    EXPECT_EQ(r.worst_cell, -1);
}

TEST(QualityRatios, IdenticalMeshesGiveAllRatiosOne) {
    const Mesh m = perturbed_hex_grid(5, 4, 3, 4);
    const auto q = cell_qualities(m, cell_orientations(m));
    const auto ratio = quality_ratios(q, q);
    ASSERT_EQ(ratio.size(), q.size());
    for (double r : ratio) EXPECT_EQ(r, 1.0);
    const RatioSummary s = summarize_ratios(ratio);
    EXPECT_EQ(s.min, 1.0);
    EXPECT_EQ(s.mean, 1.0);
    EXPECT_EQ(s.worst_cell, 0);
}

TEST(QualityRatios, NonPositiveOriginalGivesZeroAndSummaryFindsTheWorst) {
    const std::vector<double> original{0.8, 0.0, -0.2, 0.5, 0.9};
    const std::vector<double> deformed{0.4, 0.7, 0.6, 0.5, -0.45};
    const auto ratio = quality_ratios(deformed, original);
    EXPECT_EQ(ratio, (std::vector<double>{0.5, 0.0, 0.0, 1.0, -0.5}));
    const RatioSummary s = summarize_ratios(ratio);
    EXPECT_EQ(s.min, -0.5);
    EXPECT_EQ(s.worst_cell, 4);
    EXPECT_NEAR(s.mean, 0.2, 1e-15);
    // Summarised without the array: the same bits.
    const RatioSummary fused = summarize_ratios(deformed, original);
    EXPECT_EQ(fused.min, s.min);
    EXPECT_EQ(fused.mean, s.mean);
    EXPECT_EQ(fused.worst_cell, s.worst_cell);
}

TEST(QualityRatios, SummarisedWithoutTheArrayGivesTheSameBitsOnAPerturbedGrid) {
    const Mesh m = perturbed_hex_grid(6, 5, 4, 7);
    const auto original = cell_qualities(m, cell_orientations(m));
    std::vector<double> deformed = original;
    for (std::size_t i = 0; i < deformed.size(); ++i) deformed[i] *= 0.3 + 0.7 * std::sin(1.7 * static_cast<double>(i));
    const RatioSummary a = summarize_ratios(quality_ratios(deformed, original));
    const RatioSummary b = summarize_ratios(deformed, original);
    EXPECT_EQ(a.min, b.min);
    EXPECT_EQ(a.mean, b.mean);
    EXPECT_EQ(a.worst_cell, b.worst_cell);
    EXPECT_LT(a.min, 0);
}

TEST(MeshQuality, NewlyInvertedCellsAreTheValidOnesThatInverted) {
    const double nan = std::nan("");
    //                                    fine  folds  was 0  was -1  NaN now  fine->0
    const std::vector<double> original = {0.5, 0.7, 0.0, -0.2, 0.4, 0.9};
    const std::vector<double> deformed = {0.4, -0.1, -0.3, -0.2, nan, 0.0};
    EXPECT_EQ(newly_inverted_cells(deformed, original), (std::vector<std::int64_t>{1, 4, 5}));
    EXPECT_TRUE(newly_inverted_cells(original, original).empty());  // the input's own bad cells are not new
    EXPECT_TRUE(newly_inverted_cells({}, {}).empty());
}

TEST(QualityDriver, SummaryOfManyCellsIsTheOneWalkInCellOrderAtAnyThreadCount) {
    // 200k values (the sum and the counts then run side by side): random
    // qualities, every bin edge and its neighbours, NaN (first and later),
    // -0, +-inf, values above 1; against one walk in cell order.
    std::mt19937_64 rng(33);
    std::uniform_real_distribution<double> u(-0.2, 1.1);
    std::vector<double> q(200000);
    for (double& v : q) v = u(rng);
    std::size_t at = 17;
    for (int k = 0; k <= 10; ++k)
        for (double v : {k / 10.0, std::nextafter(k / 10.0, 2.0), std::nextafter(k / 10.0, -1.0)}) q[at += 97] = v;
    for (double v : {-0.0, std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity(),
                     -std::numeric_limits<double>::infinity(), 1e300, 5e-324})
        q[at += 89] = v;
    const auto walk = [](const std::vector<double>& values) {
        QualitySummary s;
        s.histogram.counts.assign(11, 0);
        OrderedSum sum;
        s.min = values[0];
        s.worst_cell = 0;
        for (std::size_t i = 0; i < values.size(); ++i) {
            const double v = values[i];
            sum.add(v);
            if (v < s.min) s.min = v, s.worst_cell = static_cast<std::int64_t>(i);
            int bin = 0;
            if (v > 0) {
                bin = 1;
                while (bin < 10 && v > bin / 10.0) ++bin;
            } else {
                ++s.inverted;
            }
            ++s.histogram.counts[static_cast<std::size_t>(bin)];
        }
        s.mean = sum.value() / static_cast<double>(values.size());
        return s;
    };
    const int threads = num_threads();
    for (bool nan_first : {false, true}) {
        if (nan_first) q[0] = std::numeric_limits<double>::quiet_NaN();
        const QualitySummary expected = walk(q);
        for (int t : {1, 2, 3}) {
            set_num_threads(t);
            const QualitySummary s = summarize_quality(q);
            EXPECT_EQ(s.histogram.counts, expected.histogram.counts) << t;
            EXPECT_EQ(s.inverted, expected.inverted) << t;
            EXPECT_EQ(std::bit_cast<std::uint64_t>(s.mean), std::bit_cast<std::uint64_t>(expected.mean)) << t;
            EXPECT_EQ(std::bit_cast<std::uint64_t>(s.min), std::bit_cast<std::uint64_t>(expected.min)) << t;
            EXPECT_EQ(s.worst_cell, expected.worst_cell) << t;
        }
    }
    set_num_threads(threads);
}
