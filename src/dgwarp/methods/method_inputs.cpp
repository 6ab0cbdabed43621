#include "dgwarp/methods/method_inputs.hpp"

#include <algorithm>
#include <cstdint>
#include <limits>
#include <string>

#include "dgwarp/methods/boundary_set_tools.hpp"

namespace dgwarp {

std::size_t check_points_and_boundary(std::string_view method, int dim, std::span<const double> points,
                                      const BoundarySet& boundary) {
    const std::size_t num_points = checked_point_count(method, dim, points);
    check_boundary_set(num_points, boundary);
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
