#include "dgwarp/methods/dg_idw_subset.hpp"

#include <string>

#include "dgwarp/core/error.hpp"
#include "dgwarp/methods/mesh_fingerprint.hpp"

namespace dgwarp {

std::vector<std::uint8_t> dg_idw_motions_read(const DgIdwPlan& plan) {
    std::vector<std::uint8_t> read(plan.boundary_nodes.size(), 0);
    for (std::int32_t b : plan.simplex_motion)
        if (b >= 0) read[static_cast<std::size_t>(b)] = 1;
    return read;
}

std::vector<std::span<const std::int32_t>> dg_idw_shared_groups(const DgIdwPlan& plan) {
    std::vector<std::span<const std::int32_t>> groups;
    for (std::size_t g = 0; g + 1 < plan.shared_offsets.size(); ++g)
        groups.emplace_back(plan.shared_members.data() + plan.shared_offsets[g],
                            static_cast<std::size_t>(plan.shared_offsets[g + 1] - plan.shared_offsets[g]));
    return groups;
}

std::vector<std::int32_t> keep_dg_idw_boundary_nodes(DgIdwPlan& plan, std::span<const std::uint8_t> keep,
                                                     std::span<const double> kept_points) {
    const std::size_t nb = plan.boundary_nodes.size();
    if (keep.size() != nb)
        throw Error("keep_dg_idw_boundary_nodes: " + std::to_string(keep.size()) + " keep flags for " +
                    std::to_string(nb) + " boundary nodes");
    std::vector<std::int32_t> renumber(nb, -1);
    std::int32_t kept = 0;
    for (std::size_t b = 0; b < nb; ++b)
        if (keep[b]) renumber[b] = kept++;
    for (std::int32_t b : plan.simplex_motion)
        if (b >= 0 && renumber[static_cast<std::size_t>(b)] < 0)
            throw Error("keep_dg_idw_boundary_nodes: boundary node " + std::to_string(plan.boundary_nodes[b]) +
                        " (boundary index " + std::to_string(b) + ") moves a graph simplex corner but is not kept");
    const std::size_t points_left = plan.node_simplex.size() - (nb - static_cast<std::size_t>(kept));
    if (kept_points.size() != points_left * static_cast<std::size_t>(plan.dim))
        throw Error("keep_dg_idw_boundary_nodes: " + std::to_string(kept_points.size()) + " coordinates for the " +
                    std::to_string(points_left) + " nodes left (dim " + std::to_string(plan.dim) + ")");

    for (std::int32_t& c : plan.simplex_motion)
        c = c >= 0 ? renumber[static_cast<std::size_t>(c)]
                   : (renumber[static_cast<std::size_t>(-1 - c)] >= 0 ? -1 - renumber[static_cast<std::size_t>(-1 - c)]
                                                                      : -1);
    // The nodes left, in their order: a boundary node's entry is its new boundary index.
    std::vector<std::int32_t> node_simplex;
    node_simplex.reserve(points_left);
    std::vector<NodeId> nodes;
    std::vector<std::uint8_t> moving;
    for (std::int32_t s : plan.node_simplex) {
        if (s >= 0) {
            node_simplex.push_back(s);
            continue;
        }
        const auto b = static_cast<std::size_t>(-1 - s);
        if (renumber[b] < 0) continue;
        nodes.push_back(static_cast<NodeId>(node_simplex.size()));
        moving.push_back(plan.boundary_moving[b]);
        node_simplex.push_back(-1 - renumber[b]);
    }
    plan.node_simplex = std::move(node_simplex);
    plan.boundary_nodes = std::move(nodes);
    plan.boundary_moving = std::move(moving);
    plan.shared_offsets = {0};
    plan.shared_members.clear();
    plan.mesh = mesh_fingerprint(plan.dim, kept_points, BoundarySet{plan.boundary_nodes, plan.boundary_moving});
    return renumber;
}

}  // namespace dgwarp
