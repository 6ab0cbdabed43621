#include "dgwarp/methods/coarse_laplacian.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

#include "dgwarp/core/error.hpp"

using namespace dgwarp;

namespace {

// Boundary vertices 0 and 1, unknowns 2, 3, 4; edges (u, v) with u < v.
const std::vector<std::pair<std::int32_t, std::int32_t>> kite_edges = {{0, 2}, {1, 2}, {0, 3}, {2, 3},
                                                                      {1, 4}, {2, 4}, {3, 4}};
constexpr std::int32_t kite_boundary = 2, kite_unknowns = 3;

using Dense = std::vector<std::vector<double>>;

// The unknowns' block of the weighted Laplacian, by hand from the edge list.
Dense laplacian_block(std::span<const double> w) {
    Dense a(kite_unknowns, std::vector<double>(kite_unknowns, 0.0));
    for (std::size_t k = 0; k < kite_edges.size(); ++k) {
        const auto [u, v] = kite_edges[k];
        a[v - kite_boundary][v - kite_boundary] += w[k];
        if (u >= kite_boundary) {
            a[u - kite_boundary][u - kite_boundary] += w[k];
            a[u - kite_boundary][v - kite_boundary] -= w[k];
            a[v - kite_boundary][u - kite_boundary] -= w[k];
        }
    }
    return a;
}

// P^T L D L^T P from the factor's arrays, in the unknowns' own order.
Dense from_factor(const HarmonicFactors& f, const HarmonicFactors::System& s) {
    const std::size_t n = f.perm.size();
    Dense l(n, std::vector<double>(n, 0.0)), a(n, std::vector<double>(n, 0.0));
    for (std::size_t j = 0; j < n; ++j) {
        l[j][j] = 1;
        for (auto k = f.l_start[j]; k < f.l_start[j + 1]; ++k)
            l[static_cast<std::size_t>(f.l_row[static_cast<std::size_t>(k)])][j] = s.l_value[static_cast<std::size_t>(k)];
    }
    Dense ldlt(n, std::vector<double>(n, 0.0));
    for (std::size_t r = 0; r < n; ++r)
        for (std::size_t c = 0; c < n; ++c)
            for (std::size_t k = 0; k < n; ++k) ldlt[r][c] += l[r][k] * s.d[k] * l[c][k];
    for (std::size_t i = 0; i < n; ++i)
        for (std::size_t j = 0; j < n; ++j)
            a[i][j] = ldlt[static_cast<std::size_t>(f.perm[i])][static_cast<std::size_t>(f.perm[j])];
    return a;
}

void expect_same(const Dense& a, const Dense& b) {
    for (std::size_t i = 0; i < a.size(); ++i)
        for (std::size_t j = 0; j < a.size(); ++j) EXPECT_NEAR(a[i][j], b[i][j], 1e-12 * (1 + std::abs(b[i][j]))) << i << "," << j;
}

}  // namespace

TEST(CoarseLaplacian, PivotCheck) {
    EXPECT_TRUE(pivots_positive(std::vector<double>{1, 2, 0.5}));
    EXPECT_FALSE(pivots_positive(std::vector<double>{1, 0, 2}));
    EXPECT_FALSE(pivots_positive(std::vector<double>{1, -1e-300}));
    EXPECT_FALSE(pivots_positive(std::vector<double>{1, std::numeric_limits<double>::quiet_NaN()}));
    EXPECT_FALSE(pivots_positive(std::vector<double>{1, 1e-20}));  // below 1e-13 of the largest: singular numerically
    EXPECT_TRUE(pivots_positive(std::vector<double>{}));
}

TEST(CoarseLaplacian, FloorRaisesOnlyWeightsBelowAFractionOfTheMean) {
    std::int64_t raised = 0;
    const std::vector<double> w = floor_weights(std::vector<double>{2, 0, 4, -1, 3e-6}, 1e-6, &raised);
    // Mean positive weight (2 + 4 + 3e-6) / 3 ≈ 2: the floor ≈ 2e-6; 3e-6 stays.
    EXPECT_EQ(raised, 2);
    EXPECT_EQ(w[0], 2);
    EXPECT_EQ(w[2], 4);
    EXPECT_EQ(w[4], 3e-6);
    EXPECT_DOUBLE_EQ(w[1], 1e-6 * ((2 + 4 + 3e-6) / 3));
    EXPECT_EQ(w[1], w[3]);
    EXPECT_EQ(floor_weights(std::vector<double>{0, 0}, 1e-6)[0], 1e-6);  // nothing positive: the floor of 1
}

TEST(CoarseLaplacian, FactorsAreTheAssembledLaplacians) {
    const std::vector<double> wt = {1, 2, 1.5, 0.5, 1, 0.25, 3}, wr = {2, 2, 1, 1, 1, 1, 1};
    std::int64_t floored = 0;
    const HarmonicFactors f = factorise_coarse_laplacian(kite_edges, wt, wr, kite_boundary, kite_unknowns, &floored);
    EXPECT_EQ(floored, 0);
    EXPECT_FALSE(f.shared);
    expect_same(from_factor(f, f.translation), laplacian_block(wt));
    expect_same(from_factor(f, f.rotation), laplacian_block(wr));
    // B: unknown 2 couples to 0 and 1, unknown 3 to 0, unknown 4 to 1.
    EXPECT_EQ(f.coupling_start, (std::vector<std::int64_t>{0, 2, 3, 4}));
    EXPECT_EQ(f.coupling_vertex, (std::vector<std::int32_t>{0, 1, 0, 1}));
    EXPECT_EQ(f.translation.coupling_weight, (std::vector<double>{1, 2, 1.5, 1}));
}

TEST(CoarseLaplacian, AZeroPivotFallsBackToFlooredWeights) {
    // Unknown 4's three edges all lost their weight (negative P1 sums set to 0):
    // its row is zero, the factorisation meets a zero pivot.
    const std::vector<double> w = {1, 2, 1.5, 0.5, 0, 0, 0};
    std::int64_t floored = 0;
    const HarmonicFactors f = factorise_coarse_laplacian(kite_edges, w, w, kite_boundary, kite_unknowns, &floored);
    EXPECT_TRUE(f.shared);
    EXPECT_EQ(floored, 3);
    std::int64_t expected_floored = 0;
    const std::vector<double> raised = floor_weights(w, 1e-6, &expected_floored);
    EXPECT_EQ(expected_floored, 3);
    expect_same(from_factor(f, f.translation), laplacian_block(raised));
    EXPECT_TRUE(pivots_positive(f.translation.d));
    // The coupling weights are the floored ones too: the step solves the floored system.
    EXPECT_EQ(f.translation.coupling_weight[3], raised[4]);
}

TEST(CoarseLaplacian, UnknownsCutOffFromTheBoundaryAreRefused) {
    // Unknowns 2 and 3 joined only to each other, 4 only to 1: no path from 2 to a boundary vertex.
    const std::vector<std::pair<std::int32_t, std::int32_t>> edges = {{1, 4}, {2, 3}};
    const std::vector<double> w = {1, 1};
    EXPECT_THROW(factorise_coarse_laplacian(edges, w, w, 2, 3), Error);
}
