#include "dgwarp/methods/plan_core.hpp"

#include "dgwarp/methods/graph_vertex_motion.hpp"
#include "dgwarp/methods/method_inputs.hpp"

namespace dgwarp {

std::size_t core_bytes(const GraphPlanCore& core) {
    return bytes_of(core.boundary_nodes) + bytes_of(core.boundary_moving) + bytes_of(core.shared_offsets) +
           bytes_of(core.shared_members) + bytes_of(core.node_simplex);
}

std::int64_t conflicting_shared_vertices(const GraphPlanCore& core, const BoundaryMotion& motion) {
    return count_conflicting_shared_vertices(core.shared_offsets, core.shared_members, core.boundary_moving, motion);
}

}  // namespace dgwarp
