#pragma once
// What the plans of the graph methods (DG-IDW, DGM, DG-harmonic) hold alike:
// the boundary set they were built for, the graph vertices standing for
// several boundary nodes, and the graph simplex of every mesh node. Each
// plan is this core and its own arrays (dg_idw.hpp, dgm.hpp, dg_harmonic.hpp).
#include <cstddef>
#include <cstdint>
#include <vector>

#include "dgwarp/mesh/mesh.hpp"
#include "dgwarp/motion/node_motion.hpp"

namespace dgwarp {

struct GraphPlanCore {
    int dim = 3;
    std::vector<NodeId> boundary_nodes;         // BoundarySet::nodes (sorted)
    std::vector<std::uint8_t> boundary_moving;  // BoundarySet::moving
    /// Graph vertices standing for several boundary nodes (same coordinates):
    /// group g holds boundary indices shared_members[shared_offsets[g] ..
    /// shared_offsets[g+1]). Rule (graph_vertex_motion.hpp): such a vertex
    /// moves if any of its nodes moves, with the motion of its first moving
    /// node (lowest boundary index).
    std::vector<std::int32_t> shared_offsets{0};
    std::vector<std::int32_t> shared_members;
    /// Per mesh node (num_points): the graph simplex of a volume node (the
    /// method's graph: DG-harmonic's coarse one), or -1 - b for the boundary
    /// node with boundary index b.
    std::vector<std::int32_t> node_simplex;

    std::int64_t num_points() const { return static_cast<std::int64_t>(node_simplex.size()); }
    std::int64_t num_volume_nodes() const { return num_points() - static_cast<std::int64_t>(boundary_nodes.size()); }
};

/// Bytes held by the core's arrays.
std::size_t core_bytes(const GraphPlanCore& core);

/// The shared graph vertices whose boundary nodes `motion` (one NodeMotion
/// per boundary index) moves differently (count_conflicting_shared_vertices):
/// what a step reports.
std::int64_t conflicting_shared_vertices(const GraphPlanCore& core, const BoundaryMotion& motion);

}  // namespace dgwarp
