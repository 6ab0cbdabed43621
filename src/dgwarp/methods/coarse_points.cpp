#include "dgwarp/methods/coarse_points.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <tuple>
#include <unordered_map>

#include "dgwarp/core/parallel_for.hpp"
#include "dgwarp/graph/morton_order.hpp"
#include "dgwarp/graph/nearest_node.hpp"

namespace dgwarp {

namespace {

// A cell of the nested grids.
struct CellKey {
    std::int32_t level;
    std::array<std::int64_t, 3> cell;
    bool operator==(const CellKey&) const = default;
};

struct CellKeyHash {
    std::size_t operator()(const CellKey& k) const {
        std::uint64_t h = static_cast<std::uint64_t>(k.level) * 0x9e3779b97f4a7c15ULL;
        for (std::int64_t c : k.cell) h = (h ^ static_cast<std::uint64_t>(c)) * 0xff51afd7ed558ccdULL;
        return static_cast<std::size_t>(h ^ (h >> 32));
    }
};

// The best node of a cell so far.
struct Candidate {
    double centre_dist2;
    NodeId node;
};

}  // namespace

std::vector<NodeId> select_coarse_points(int dim, std::span<const double> points,
                                         std::span<const NodeId> boundary_nodes,
                                         std::span<const NodeId> volume_nodes, const CoarseSpacing& spacing) {
    if (boundary_nodes.empty() || volume_nodes.empty()) return {};
    const NearestNode tree(dim, points, boundary_nodes);
    std::vector<double> h(boundary_nodes.size());
    parallel_for(static_cast<std::int64_t>(h.size()), [&](std::int64_t j) { h[j] = tree.spacing(j); });

    // The spacing each volume node wants (0: not a candidate). Queried along a
    // Morton curve: neighbouring queries then walk the same tree branches.
    // want_sorted[k]: of volume node order[k]; the nodes' points gathered in
    // that order first, so that the queries read them in sequence.
    std::vector<double> want_sorted(volume_nodes.size());
    const std::vector<std::uint32_t> order = morton_order(dim, points, volume_nodes);
    std::vector<double> sorted_points(volume_nodes.size() * static_cast<std::size_t>(dim));
    parallel_for(static_cast<std::int64_t>(volume_nodes.size()), [&](std::int64_t k) {
        std::copy_n(points.data() + static_cast<std::size_t>(volume_nodes[order[k]]) * dim, dim,
                    sorted_points.data() + k * dim);
    });
    parallel_for(static_cast<std::int64_t>(volume_nodes.size()), [&](std::int64_t k) {
        const double* x = sorted_points.data() + k * dim;
        // A spacing needs no exact distance: within 50% it is as good.
        const NearestNode::Found f = tree.nearest(x, 0.5);
        const double d = f.distance;
        const double s = std::max(spacing.wall_spacing * h[f.index], spacing.growth * d);
        want_sorted[k] = d > 0 && d >= 0.5 * s ? s : 0.0;
    });

    double s_min = std::numeric_limits<double>::infinity();
    std::array<double, 3> lo{std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity(),
                             std::numeric_limits<double>::infinity()};
    for (std::size_t k = 0; k < volume_nodes.size(); ++k) {
        if (want_sorted[k] > 0) s_min = std::min(s_min, want_sorted[k]);
        for (int d = 0; d < dim; ++d) lo[d] = std::min(lo[d], sorted_points[k * dim + d]);
    }
    if (!std::isfinite(s_min)) return {};

    // Per (level, cell), the candidate nearest to the cell's centre (lowest id
    // on ties: the result does not depend on the visiting order, and the Morton
    // order keeps the cells visited one after another close in the table).
    std::unordered_map<CellKey, Candidate, CellKeyHash> best;
    best.reserve(volume_nodes.size() / 8);
    for (std::size_t j = 0; j < volume_nodes.size(); ++j) {
        const double want = want_sorted[j];
        if (want <= 0) continue;
        CellKey key{};
        key.level = static_cast<std::int32_t>(std::floor(std::log2(want / s_min)));
        const double size = std::ldexp(s_min, key.level);
        const double* x = sorted_points.data() + j * dim;
        Candidate k{0.0, volume_nodes[order[j]]};
        for (int d = 0; d < dim; ++d) {
            const double u = (x[d] - lo[d]) / size;
            key.cell[d] = static_cast<std::int64_t>(std::floor(u));
            const double off = u - (static_cast<double>(key.cell[d]) + 0.5);
            k.centre_dist2 += off * off;
        }
        const auto [it, inserted] = best.try_emplace(key, k);
        if (!inserted && std::tie(k.centre_dist2, k.node) < std::tie(it->second.centre_dist2, it->second.node))
            it->second = k;
    }
    std::vector<NodeId> chosen;
    chosen.reserve(best.size());
    for (const auto& [key, k] : best) chosen.push_back(k.node);
    std::sort(chosen.begin(), chosen.end());
    return chosen;
}

}  // namespace dgwarp
