// prepare_idw and the option checks of global IDW.
#include "dgwarp/methods/idw.hpp"

#include <cmath>
#include <string>

#include "dgwarp/core/error.hpp"
#include "dgwarp/methods/boundary_set_tools.hpp"

namespace dgwarp {

void check_idw_options(const IdwOptions& options) {
    auto exponent_ok = [](double c) { return std::isfinite(c) && c > 0 && c <= 16; };
    if (!exponent_ok(options.exponent_moving) || !exponent_ok(options.exponent_static))
        throw Error("IDW: exponent_moving and exponent_static must be in (0, 16], got " +
                    std::to_string(options.exponent_moving) + " and " + std::to_string(options.exponent_static));
    if (!std::isfinite(options.length_scale) || options.length_scale < 0)
        throw Error("IDW: length_scale must be finite and >= 0 (0 = auto), got " +
                    std::to_string(options.length_scale));
}

IdwPlan prepare_idw(int dim, std::span<const double> points, const BoundarySet& boundary,
                    const IdwOptions& options) {
    const std::size_t num_points = checked_point_count("IDW", dim, points);
    check_idw_options(options);
    check_boundary_set(num_points, boundary);
    if (boundary.nodes.empty()) throw MeshError("IDW needs at least one boundary node, the boundary set is empty");

    IdwPlan plan;
    plan.dim = dim;
    plan.num_points = static_cast<std::int64_t>(num_points);
    plan.boundary_nodes = boundary.nodes;
    plan.boundary_moving = boundary.moving;
    const double moving = boundary_diagonal(dim, points, boundary, true);
    const double all = boundary_diagonal(dim, points, boundary, false);
    plan.auto_length_scale = moving > 0 ? moving : all > 0 ? all : 1.0;
    plan.boundary_points.reserve(boundary.nodes.size() * static_cast<std::size_t>(dim));
    for (NodeId n : boundary.nodes)
        for (int d = 0; d < dim; ++d) plan.boundary_points.push_back(points[static_cast<std::size_t>(n) * dim + d]);
    return plan;
}

std::size_t plan_bytes(const IdwPlan& plan) {
    return plan.boundary_nodes.capacity() * sizeof(NodeId) + plan.boundary_moving.capacity() +
           plan.boundary_points.capacity() * sizeof(double);
}

}  // namespace dgwarp
