#include "dgwarp/methods/method_inputs.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>

#include "dgwarp/core/error.hpp"
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

void check_step_arrays(std::string_view method, std::int64_t num_points, int dim,
                       std::span<const NodeId> boundary_nodes, std::span<const double> points,
                       const BoundaryMotion& motion, std::span<const double> out) {
    const std::string name(method);
    const auto expected = static_cast<std::size_t>(num_points) * static_cast<std::size_t>(dim);
    if (points.size() != expected)
        throw MeshError(name + ": the plan is for " + std::to_string(num_points) + " points (" +
                        std::to_string(expected) + " coordinates), got " + std::to_string(points.size()) +
                        " coordinates");
    if (out.size() != expected)
        throw MeshError(name + ": the output array holds " + std::to_string(out.size()) + " values, expected " +
                        std::to_string(expected) + " (" + std::to_string(num_points) + " points)");
    if (motion.size() != boundary_nodes.size())
        throw MeshError(name + ": the motion has " + std::to_string(motion.size()) + " entries but the plan has " +
                        std::to_string(boundary_nodes.size()) + " boundary nodes");
    for (std::size_t b = 0; b < motion.size(); ++b) {
        const NodeMotion& m = motion[b];
        for (int d = 0; d < 3; ++d)
            if (!std::isfinite(m.translation[d]) || !std::isfinite(m.rotation[d]) || !std::isfinite(m.center[d]))
                throw MeshError(name + ": the motion of boundary node " + std::to_string(boundary_nodes[b]) +
                                    " (boundary index " + std::to_string(b) + ") is not finite",
                                {}, boundary_nodes[b]);
    }
}

}  // namespace dgwarp

