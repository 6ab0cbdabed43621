#include "dgwarp/methods/method_inputs.hpp"

#include <algorithm>
#include <cstdint>
#include <limits>
#include <string>

#include "dgwarp/core/error.hpp"

namespace dgwarp {

std::size_t check_points_and_boundary(std::string_view method, int dim, std::span<const double> points,
                                      const BoundarySet& boundary) {
    const std::string name(method);
    if (dim != 2 && dim != 3) throw MeshError(name + " needs dim 2 or 3, got " + std::to_string(dim));
    if (points.size() % static_cast<std::size_t>(dim) != 0)
        throw MeshError("the point array holds " + std::to_string(points.size()) +
                        " values, not a whole number of " + std::to_string(dim) + "D points");
    const std::size_t num_points = points.size() / static_cast<std::size_t>(dim);
    if (num_points > static_cast<std::size_t>(std::numeric_limits<std::int32_t>::max()))
        throw MeshError("the mesh has " + std::to_string(num_points) + " points, more than int32 node ids can hold");
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
    return num_points;
}

std::vector<NodeId> split_volume_nodes(std::size_t num_points, const BoundarySet& boundary,
                                       std::vector<std::int32_t>& node_simplex) {
    std::vector<NodeId> volume;
    volume.reserve(num_points - std::min(num_points, boundary.nodes.size()));
    node_simplex.assign(num_points, 0);
    for (std::size_t n = 0, b = 0; n < num_points; ++n) {
        if (b < boundary.nodes.size() && static_cast<std::size_t>(boundary.nodes[b]) == n) {
            node_simplex[n] = -1 - static_cast<std::int32_t>(b++);
        } else {
            volume.push_back(static_cast<NodeId>(n));
        }
    }
    return volume;
}

}  // namespace dgwarp
