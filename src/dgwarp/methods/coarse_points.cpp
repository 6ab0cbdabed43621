#include "dgwarp/methods/coarse_points.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <tuple>

#include "dgwarp/core/parallel_for.hpp"
#include "dgwarp/graph/nearest_node.hpp"

namespace dgwarp {

namespace {

struct Candidate {
    std::int32_t level;
    std::array<std::int64_t, 3> cell;
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

    // The spacing each volume node wants (0: not a candidate).
    std::vector<double> want(volume_nodes.size());
    parallel_for(static_cast<std::int64_t>(volume_nodes.size()), [&](std::int64_t i) {
        const double* x = points.data() + static_cast<std::size_t>(volume_nodes[i]) * dim;
        const NearestNode::Found f = tree.nearest(x);
        const double d = f.distance;
        const double s = std::max(spacing.wall_spacing * h[f.index], spacing.growth * d);
        want[i] = d > 0 && d >= 0.5 * s ? s : 0.0;
    });

    double s_min = std::numeric_limits<double>::infinity();
    std::array<double, 3> lo{std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity(),
                             std::numeric_limits<double>::infinity()};
    for (std::size_t i = 0; i < volume_nodes.size(); ++i) {
        if (want[i] > 0) s_min = std::min(s_min, want[i]);
        for (int d = 0; d < dim; ++d) lo[d] = std::min(lo[d], points[static_cast<std::size_t>(volume_nodes[i]) * dim + d]);
    }
    if (!std::isfinite(s_min)) return {};

    std::vector<Candidate> c;
    c.reserve(volume_nodes.size());
    for (std::size_t i = 0; i < volume_nodes.size(); ++i) {
        if (want[i] <= 0) continue;
        Candidate k{};
        k.level = static_cast<std::int32_t>(std::floor(std::log2(want[i] / s_min)));
        const double size = std::ldexp(s_min, k.level);
        const double* x = points.data() + static_cast<std::size_t>(volume_nodes[i]) * dim;
        for (int d = 0; d < dim; ++d) {
            const double u = (x[d] - lo[d]) / size;
            k.cell[d] = static_cast<std::int64_t>(std::floor(u));
            const double off = u - (static_cast<double>(k.cell[d]) + 0.5);
            k.centre_dist2 += off * off;
        }
        k.node = volume_nodes[i];
        c.push_back(k);
    }
    std::sort(c.begin(), c.end(), [](const Candidate& a, const Candidate& b) {
        return std::tie(a.level, a.cell, a.centre_dist2, a.node) < std::tie(b.level, b.cell, b.centre_dist2, b.node);
    });
    std::vector<NodeId> chosen;
    for (std::size_t i = 0; i < c.size(); ++i)
        if (i == 0 || c[i].level != c[i - 1].level || c[i].cell != c[i - 1].cell) chosen.push_back(c[i].node);
    std::sort(chosen.begin(), chosen.end());
    return chosen;
}

}  // namespace dgwarp
