#include "dgwarp/methods/coarse_points.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <mutex>
#include <tuple>
#include <unordered_map>

#include "dgwarp/core/parallel_for.hpp"
#include "dgwarp/graph/delaunay_graph.hpp"
#include "dgwarp/graph/morton_order.hpp"
#include "dgwarp/graph/nearest_node.hpp"
#include "dgwarp/methods/nearest_boundary_cells.hpp"

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

CoarseWants coarse_wants(int dim, std::span<const double> points, std::span<const NodeId> boundary_nodes,
                         std::span<const NodeId> volume_nodes, const CoarseSpacing& spacing,
                         std::span<const std::uint32_t> morton) {
    constexpr double inf = std::numeric_limits<double>::infinity();
    CoarseWants w{std::vector<double>(volume_nodes.size(), 0.0), inf, {inf, inf, inf}};
    if (boundary_nodes.empty() || volume_nodes.empty()) return w;
    const NearestNode tree(dim, points, boundary_nodes);
    std::vector<double> h(boundary_nodes.size());
    parallel_for(static_cast<std::int64_t>(h.size()), [&](std::int64_t j) { h[j] = tree.spacing(j); });

    // The spacing each volume node wants (0: not a candidate). Visited in a
    // spatially coherent order (the given one when it is, else along a Morton
    // curve): neighbouring nodes then fall in the same cells and walk the same
    // tree branches. The nodes' points are gathered in a Morton order first,
    // so that the visits read them in sequence (826k nodes in Gmsh's random
    // numbering, under load: the whole selection 1.3 -> 0.75 s).
    std::vector<double>& want = w.want;
    std::vector<std::uint32_t> own;
    if (morton.size() != volume_nodes.size() && !is_coherent_order(dim, points, volume_nodes)) {
        own = morton_order(dim, points, volume_nodes);
        morton = own;
    }
    const bool given = morton.size() != volume_nodes.size();
    std::vector<double> sorted_points;
    if (!given) {
        sorted_points.resize(volume_nodes.size() * static_cast<std::size_t>(dim));
        parallel_for(static_cast<std::int64_t>(volume_nodes.size()), [&](std::int64_t k) {
            const double* x = points.data() + static_cast<std::size_t>(volume_nodes[morton[k]]) * dim;
            for (int d = 0; d < dim; ++d) sorted_points[k * dim + d] = x[d];
        });
    }
    // Most nodes take the nearest of their leaf's boundary nodes
    // (nearest_boundary_cells.hpp). A node outside the boundary's cube, or
    // whose wall distance may be under half the wall spacing (where whether it
    // is a candidate, and the smallest want that sets the grids, hang on its
    // own nearest node), asks the k-d tree. Either way its want depends on its
    // coordinates only.
    // The k-th node of the visit order: its position in volume_nodes, its point.
    auto node_at = [&](std::size_t k) -> std::size_t { return given ? k : morton[k]; };
    auto point_at = [&](std::size_t k) {
        return given ? points.data() + static_cast<std::size_t>(volume_nodes[k]) * dim : sorted_points.data() + k * dim;
    };
    auto want_of = [&](double d, std::int64_t j) {
        const double s = std::max(spacing.wall_spacing * h[j], spacing.growth * d);
        return d > 0 && d >= 0.5 * s ? s : 0.0;
    };
    // A run of the visit order per thread, each with cells of its own (an
    // answer depends on the node's coordinates only, not on which cells
    // were made before it).
    std::vector<std::uint8_t> asked(volume_nodes.size(), 0);  // by position in the visit order
    parallel_for_chunks(static_cast<std::int64_t>(volume_nodes.size()), [&](std::int64_t first, std::int64_t last) {
        NearestBoundaryCells cells(dim, points, boundary_nodes, tree, h, spacing);
        for (auto k = static_cast<std::size_t>(first); k < static_cast<std::size_t>(last); ++k) {
            const NearestBoundaryCells::Answer a = cells.find(point_at(k));
            if (a.index >= 0) want[node_at(k)] = want_of(a.distance, a.index);
            asked[k] = a.index < 0 || a.lower_bound < 0.5 * spacing.wall_spacing * h[a.index];
        }
    });
    std::vector<std::int64_t> ask;  // positions in the visit order
    for (std::size_t k = 0; k < asked.size(); ++k)
        if (asked[k]) ask.push_back(static_cast<std::int64_t>(k));
    parallel_for(static_cast<std::int64_t>(ask.size()), [&](std::int64_t a) {
        const auto k = static_cast<std::size_t>(ask[a]);
        // A spacing needs no exact distance: within 50% it is as good.
        const NearestNode::Found f = tree.nearest(point_at(k), 0.5);
        want[node_at(k)] = want_of(f.distance, f.index);
    });
    for (double s : want)
        if (s > 0) w.s_min = std::min(w.s_min, s);
    const BoundingBox box = bounding_box(dim, points, volume_nodes);
    for (int d = 0; d < dim; ++d) w.lo[d] = box.min[d];
    return w;
}

std::vector<CoarseWinner> coarse_cell_winners(int dim, std::span<const double> points,
                                              std::span<const NodeId> volume_nodes, std::span<const double> want,
                                              double s_min, const std::array<double, 3>& lo) {
    if (!std::isfinite(s_min)) return {};
    // Per (level, cell), the candidate nearest to the cell's centre (lowest id on ties).
    std::unordered_map<CellKey, Candidate, CellKeyHash> best;
    best.reserve(volume_nodes.size() / 8);
    for (std::size_t i = 0; i < volume_nodes.size(); ++i) {
        if (want[i] <= 0) continue;
        CellKey key{};
        key.level = static_cast<std::int32_t>(std::floor(std::log2(want[i] / s_min)));
        const double size = std::ldexp(s_min, key.level);
        const double* x = points.data() + static_cast<std::size_t>(volume_nodes[i]) * dim;
        Candidate k{0.0, volume_nodes[i]};
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
    std::vector<CoarseWinner> winners;
    winners.reserve(best.size());
    for (const auto& [key, k] : best) winners.push_back({key.level, key.cell, k.centre_dist2, k.node});
    return winners;
}

std::vector<NodeId> merge_coarse_winners(std::span<const CoarseWinner> winners) {
    std::unordered_map<CellKey, Candidate, CellKeyHash> best;
    best.reserve(winners.size());
    for (const CoarseWinner& w : winners) {
        const Candidate k{w.centre_dist2, w.node};
        const auto [it, inserted] = best.try_emplace(CellKey{w.level, w.cell}, k);
        if (!inserted && std::tie(k.centre_dist2, k.node) < std::tie(it->second.centre_dist2, it->second.node))
            it->second = k;
    }
    std::vector<NodeId> chosen;
    chosen.reserve(best.size());
    for (const auto& [key, k] : best) chosen.push_back(k.node);
    std::sort(chosen.begin(), chosen.end());
    chosen.erase(std::unique(chosen.begin(), chosen.end()), chosen.end());
    return chosen;
}

std::vector<NodeId> select_coarse_points(int dim, std::span<const double> points,
                                         std::span<const NodeId> boundary_nodes,
                                         std::span<const NodeId> volume_nodes, const CoarseSpacing& spacing,
                                         std::span<const std::uint32_t> morton) {
    const CoarseWants w = coarse_wants(dim, points, boundary_nodes, volume_nodes, spacing, morton);
    // The winners of a run of nodes per thread, merged as the parts of a
    // distributed mesh are (the same nodes as one run over them all, in
    // whatever order the runs' winners come).
    std::vector<CoarseWinner> winners;
    std::mutex joining;
    parallel_for_chunks(static_cast<std::int64_t>(volume_nodes.size()), [&](std::int64_t first, std::int64_t last) {
        const auto at = static_cast<std::size_t>(first), count = static_cast<std::size_t>(last - first);
        const std::vector<CoarseWinner> mine = coarse_cell_winners(
            dim, points, volume_nodes.subspan(at, count), std::span<const double>(w.want).subspan(at, count), w.s_min, w.lo);
        const std::lock_guard lock(joining);
        winners.insert(winners.end(), mine.begin(), mine.end());
    });
    return merge_coarse_winners(winners);
}

}  // namespace dgwarp
