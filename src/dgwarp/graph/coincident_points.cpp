#include "dgwarp/graph/coincident_points.hpp"

#include <algorithm>
#include <numeric>

namespace dgwarp {

CoincidentGroups group_coincident_points(int dim, std::span<const double> points,
                                         std::span<const NodeId> nodes) {
    const auto n = static_cast<std::int32_t>(nodes.size());
    auto coord = [&](std::int32_t k, int d) { return points[static_cast<std::size_t>(nodes[k]) * dim + d]; };
    auto less = [&](std::int32_t a, std::int32_t b) {
        for (int d = 0; d < dim; ++d) {
            const double x = coord(a, d), y = coord(b, d);
            if (x != y) return x < y;
        }
        return a < b;  // equal points: by list position, so groups come out ascending
    };
    auto equal = [&](std::int32_t a, std::int32_t b) {
        for (int d = 0; d < dim; ++d)
            if (coord(a, d) != coord(b, d)) return false;
        return true;
    };
    std::vector<std::int32_t> order(static_cast<std::size_t>(n));
    std::iota(order.begin(), order.end(), 0);
    std::sort(order.begin(), order.end(), less);

    // first_of[k]: the smallest list position with k's coordinates.
    std::vector<std::int32_t> first_of(static_cast<std::size_t>(n));
    for (std::int32_t i = 0; i < n;) {
        std::int32_t j = i + 1;
        while (j < n && equal(order[i], order[j])) ++j;
        for (std::int32_t k = i; k < j; ++k) first_of[order[k]] = order[i];
        i = j;
    }
    // Number groups by their first member; count, then fill.
    std::vector<std::int32_t> group_of(static_cast<std::size_t>(n), -1);
    CoincidentGroups groups;
    std::vector<std::int32_t> counts;
    for (std::int32_t k = 0; k < n; ++k) {
        if (first_of[k] == k) {
            group_of[k] = static_cast<std::int32_t>(counts.size());
            counts.push_back(0);
        }
        ++counts[group_of[first_of[k]]];
    }
    groups.offsets.resize(counts.size() + 1);
    for (std::size_t g = 0; g < counts.size(); ++g) groups.offsets[g + 1] = groups.offsets[g] + counts[g];
    groups.members.resize(static_cast<std::size_t>(n));
    std::vector<std::int32_t> fill(groups.offsets.begin(), groups.offsets.end() - 1);
    for (std::int32_t k = 0; k < n; ++k) groups.members[fill[group_of[first_of[k]]]++] = k;
    return groups;
}

}  // namespace dgwarp
