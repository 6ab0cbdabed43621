#include "dgwarp/graph/morton_order.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <random>

using namespace dgwarp;

namespace {

// Brute force: the Morton code bit by bit (axis d's bit k at position k * dim + d)
// of each node's cell in a grid of 2^bits - 1 cells over the nodes' bounding box.
std::vector<std::uint64_t> morton_codes_bit_by_bit(int dim, const std::vector<double>& points,
                                                   const std::vector<NodeId>& nodes) {
    const int bits = dim == 3 ? 21 : 32;
    const double cells = std::ldexp(1.0, bits) - 1;
    std::vector<double> lo(dim, INFINITY), hi(dim, -INFINITY);
    for (NodeId n : nodes)
        for (int d = 0; d < dim; ++d) {
            lo[d] = std::min(lo[d], points[n * dim + d]);
            hi[d] = std::max(hi[d], points[n * dim + d]);
        }
    std::vector<std::uint64_t> codes;
    for (NodeId n : nodes) {
        std::uint64_t code = 0;
        for (int d = 0; d < dim; ++d) {
            const double scale = hi[d] > lo[d] ? cells / (hi[d] - lo[d]) : 0.0;
            const auto c = static_cast<std::uint64_t>(std::clamp((points[n * dim + d] - lo[d]) * scale, 0.0, cells));
            for (int k = 0; k < bits; ++k) code |= ((c >> k) & 1) << (k * dim + d);
        }
        codes.push_back(code);
    }
    return codes;
}

}  // namespace

TEST(GraphMortonOrder, SortsByCodeWithTiesInGivenOrder) {
    std::mt19937 rng(42);
    std::uniform_real_distribution<double> u(-3, 7);
    for (int dim : {2, 3}) {
        // Random points, some repeated (ties), one axis flat for the first test points.
        std::vector<double> points;
        for (int i = 0; i < 20000; ++i)
            for (int d = 0; d < dim; ++d) points.push_back(u(rng));
        for (int i = 0; i < 500; ++i)
            for (int d = 0; d < dim; ++d) points.push_back(points[(i * 7) * dim + d]);
        std::vector<NodeId> nodes(points.size() / dim);
        std::iota(nodes.begin(), nodes.end(), 0);
        std::shuffle(nodes.begin(), nodes.end(), rng);
        nodes.resize(nodes.size() - 100);  // a subset, in a random order

        const std::vector<std::uint32_t> order = morton_order(dim, points, nodes);
        const std::vector<std::uint64_t> codes = morton_codes_bit_by_bit(dim, points, nodes);
        std::vector<std::uint32_t> expected(nodes.size());
        std::iota(expected.begin(), expected.end(), 0u);
        std::stable_sort(expected.begin(), expected.end(),
                         [&](std::uint32_t a, std::uint32_t b) { return codes[a] < codes[b]; });
        EXPECT_EQ(order, expected) << dim << "D";
    }
}

TEST(GraphMortonOrder, ClusteredNodesSortedByEveryBit) {
    // Most nodes packed into a corner a millionth of the box wide (a boundary
    // layer's): their codes agree in the high bits, so the order among them
    // comes from the low bits alone.
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> u(0, 1);
    for (int dim : {2, 3}) {
        std::vector<double> points;
        for (int i = 0; i < 6000; ++i)
            for (int d = 0; d < dim; ++d) points.push_back(i < 200 ? u(rng) : 0.25 + 1e-6 * u(rng));
        for (int i = 0; i < 300; ++i)  // repeated points: ties
            for (int d = 0; d < dim; ++d) points.push_back(points[(i * 13 + 250) * dim + d]);
        std::vector<NodeId> nodes(points.size() / dim);
        std::iota(nodes.begin(), nodes.end(), 0);
        std::shuffle(nodes.begin(), nodes.end(), rng);

        const std::vector<std::uint64_t> codes = morton_codes_bit_by_bit(dim, points, nodes);
        std::vector<std::uint32_t> expected(nodes.size());
        std::iota(expected.begin(), expected.end(), 0u);
        std::stable_sort(expected.begin(), expected.end(),
                         [&](std::uint32_t a, std::uint32_t b) { return codes[a] < codes[b]; });
        EXPECT_EQ(morton_order(dim, points, nodes), expected) << dim << "D";
        std::size_t sharing_high_bits = 0;  // the test's premise
        for (std::size_t k = 1; k < expected.size(); ++k)
            sharing_high_bits += codes[expected[k]] >> 33 == codes[expected[k - 1]] >> 33;
        EXPECT_GT(sharing_high_bits, 5000u) << dim << "D";
    }
}

TEST(GraphMortonOrder, FlatAxisEmptyAndSingleNode) {
    // All points on the plane z = 1: that axis contributes nothing.
    const std::vector<double> points = {0, 0, 1, 1, 1, 1, 1, 0, 1, 0, 1, 1};
    EXPECT_EQ(morton_order(3, points, std::vector<NodeId>{0, 1, 2, 3}), (std::vector<std::uint32_t>{0, 2, 3, 1}));
    EXPECT_TRUE(morton_order(3, points, std::vector<NodeId>{}).empty());
    EXPECT_EQ(morton_order(3, points, std::vector<NodeId>{2}), (std::vector<std::uint32_t>{0}));
}
