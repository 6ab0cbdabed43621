// mesh_parts.hpp: the nodes of each part's cells, in order of first use.
#include "dgwarp/mpi/mesh_parts.hpp"

#include "dgwarp/core/error.hpp"
#include "dgwarp/methods/boundary_set_tools.hpp"
#include "dgwarp/mpi/morton_partition.hpp"

namespace dgwarp::mpi {

std::vector<NodePart> split_mesh(const Mesh& mesh, const BoundarySet& boundary, int parts,
                                 const std::vector<std::vector<NodeId>>& node_parts) {
    if (parts < 1) throw UsageError("split_mesh: " + std::to_string(parts) + " parts (at least 1)");
    const std::size_t n = mesh.num_points();
    std::vector<NodePart> out(static_cast<std::size_t>(parts));
    // A mark per part and node (bits): a part's cells are not contiguous, so
    // remembering only the last part that took a node would have a part take
    // it again after another part's cell.
    std::vector<std::vector<bool>> taken(static_cast<std::size_t>(parts), std::vector<bool>(n, false));
    std::vector<std::uint8_t> held(n, 0);  // by some part
    check_boundary_set(n, boundary);
    std::vector<std::int32_t> boundary_slot(n, -1);
    for (std::size_t b = 0; b < boundary.nodes.size(); ++b)
        boundary_slot[static_cast<std::size_t>(boundary.nodes[b])] = static_cast<std::int32_t>(b);
    auto take = [&](int r, NodeId node) {
        if (node < 0 || static_cast<std::size_t>(node) >= n)
            throw MeshError("split_mesh: node " + std::to_string(node) + " of part " + std::to_string(r) +
                                " is not a node of a mesh of " + std::to_string(n),
                            {}, node);
        const auto i = static_cast<std::size_t>(node);
        std::vector<bool>::reference mark = taken[static_cast<std::size_t>(r)][i];
        if (mark) return;
        mark = true;
        held[i] = 1;
        NodePart& p = out[static_cast<std::size_t>(r)];
        const auto local = static_cast<NodeId>(p.global_ids.size());
        p.global_ids.push_back(node);
        for (int d = 0; d < mesh.dim; ++d) p.points.push_back(mesh.points[i * static_cast<std::size_t>(mesh.dim) + d]);
        if (boundary_slot[i] >= 0) {
            p.boundary.nodes.push_back(local);  // ascending: locals are numbered in order
            p.boundary.moving.push_back(boundary.moving[static_cast<std::size_t>(boundary_slot[i])]);
            p.slots.push_back(boundary_slot[i]);
        }
    };
    if (node_parts.size() == static_cast<std::size_t>(parts)) {
        for (int r = 0; r < parts; ++r)
            for (NodeId node : node_parts[static_cast<std::size_t>(r)]) take(r, node);
    } else {
        const std::vector<std::int32_t> cell_part = morton_cell_parts(mesh, parts);
        for (std::size_t c = 0; c < mesh.cells.types.size(); ++c)
            for (std::int64_t k = mesh.cells.offsets[c]; k < mesh.cells.offsets[c + 1]; ++k)
                take(cell_part[c], mesh.cells.nodes[static_cast<std::size_t>(k)]);
    }
    for (std::size_t node = 0; node < n; ++node)
        if (!held[node]) take(0, static_cast<NodeId>(node));
    return out;
}

}  // namespace dgwarp::mpi
