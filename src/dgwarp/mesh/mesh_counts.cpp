// mesh_counts.hpp: a mesh's nodes, cells by type and markers, counted.
#include "dgwarp/mesh/mesh_counts.hpp"

namespace dgwarp {

MeshCounts mesh_counts(const Mesh& mesh) {
    MeshCounts c;
    c.dim = mesh.dim;
    c.nodes = static_cast<std::int64_t>(mesh.num_points());
    c.cells = static_cast<std::int64_t>(mesh.cells.size());
    const auto counts = count_by_type(mesh.cells);
    c.cell_types.assign(counts.begin(), counts.end());
    for (const Marker& m : mesh.markers)
        c.markers.push_back({m.name, static_cast<std::int64_t>(m.elements.size()),
                             static_cast<std::int64_t>(marker_nodes(m).size())});
    return c;
}

}  // namespace dgwarp
