#include "dgwarp/methods/boundary_set_tools.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>

#include "dgwarp/core/error.hpp"

namespace dgwarp {

std::size_t checked_point_count(std::string_view method, int dim, std::span<const double> points) {
    const std::string name(method);
    if (dim != 2 && dim != 3) throw MeshError(name + " needs dim 2 or 3, got " + std::to_string(dim));
    if (points.size() % static_cast<std::size_t>(dim) != 0)
        throw MeshError("the point array holds " + std::to_string(points.size()) +
                        " values, not a whole number of " + std::to_string(dim) + "D points");
    const std::size_t num_points = points.size() / static_cast<std::size_t>(dim);
    if (num_points > static_cast<std::size_t>(std::numeric_limits<std::int32_t>::max()))
        throw MeshError("the mesh has " + std::to_string(num_points) + " points, more than int32 node ids can hold");
    return num_points;
}

void check_boundary_set(std::size_t num_points, const BoundarySet& boundary) {
    if (boundary.moving.size() != boundary.nodes.size())
        throw MeshError("the boundary set has " + std::to_string(boundary.nodes.size()) + " nodes but " +
                        std::to_string(boundary.moving.size()) + " moving flags");
    for (std::size_t b = 0; b < boundary.nodes.size(); ++b) {
        const NodeId n = boundary.nodes[b];
        if (n < 0 || static_cast<std::size_t>(n) >= num_points)
            throw MeshError("boundary node id " + std::to_string(n) + " is out of range (the mesh has " +
                                std::to_string(num_points) + " points)",
                            {}, n);
        if (b > 0 && n <= boundary.nodes[b - 1])
            throw MeshError("boundary node ids must be sorted and unique; node " + std::to_string(n) +
                                " follows node " + std::to_string(boundary.nodes[b - 1]),
                            {}, n);
        if (boundary.moving[b] > 1)
            throw MeshError("boundary node " + std::to_string(n) + " has moving flag " +
                                std::to_string(int(boundary.moving[b])) + " (expected 0 or 1)",
                            {}, n);
    }
}

double boundary_diagonal(int dim, std::span<const double> points, const BoundarySet& boundary, bool moving_only) {
    double lo[3] = {std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity(),
                    std::numeric_limits<double>::infinity()};
    double hi[3] = {-lo[0], -lo[1], -lo[2]};
    bool found = false;
    for (std::size_t b = 0; b < boundary.nodes.size(); ++b) {
        if (moving_only && !boundary.moving[b]) continue;
        found = true;
        for (int d = 0; d < dim; ++d) {
            const double x = points[static_cast<std::size_t>(boundary.nodes[b]) * dim + d];
            lo[d] = std::min(lo[d], x);
            hi[d] = std::max(hi[d], x);
        }
    }
    if (!found) return 0;
    double s = 0;
    for (int d = 0; d < dim; ++d) s += (hi[d] - lo[d]) * (hi[d] - lo[d]);
    return std::sqrt(s);
}

NodeId volume_node_id(std::span<const NodeId> boundary, std::int64_t v) {
    // g_i = boundary[i] - i volume nodes precede boundary node i, and g is
    // non-decreasing: the answer is v + (number of i with g_i <= v).
    std::int64_t lo = 0, hi = static_cast<std::int64_t>(boundary.size());
    while (lo < hi) {
        const std::int64_t mid = (lo + hi) / 2;
        if (boundary[mid] - mid <= v) lo = mid + 1;
        else hi = mid;
    }
    return static_cast<NodeId>(v + lo);
}

}  // namespace dgwarp
