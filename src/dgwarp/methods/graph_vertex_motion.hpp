#pragma once
// How the vertices of the Delaunay graph move, shared by DG-IDW and DGM.
// Boundary nodes with identical coordinates are one graph vertex
// (METHODS.md, DG-IDW prepare step 1). Rule: such a vertex moves if any of its
// boundary nodes moves, with the motion of its first moving node (lowest
// boundary index); otherwise it is static.
#include <cstdint>
#include <span>
#include <vector>

#include "dgwarp/graph/delaunay_graph.hpp"
#include "dgwarp/motion/node_motion.hpp"

namespace dgwarp {

struct GraphVertexMotion {
    /// Per graph vertex: b >= 0 when it moves, with the motion of boundary
    /// index b; -1 - b when it is static (b its first boundary index).
    std::vector<std::int32_t> vertex_motion;
    /// Graph vertices standing for several boundary nodes: group g holds
    /// boundary indices members[offsets[g] .. offsets[g+1]), ascending.
    std::vector<std::int32_t> shared_offsets{0};
    std::vector<std::int32_t> shared_members;
};

/// The motion source of every vertex of `graph` under the rule above.
/// moving: the BoundarySet's moving flags (one per boundary index).
GraphVertexMotion graph_vertex_motion(const DelaunayGraph& graph, std::span<const std::uint8_t> moving);

/// Shared graph vertices (groups as in GraphVertexMotion) whose boundary nodes
/// have different motions this step: a moving member whose NodeMotion differs
/// from the one used, or a static member of a vertex that moves. moving: one
/// flag per boundary index; motion: one NodeMotion per boundary index.
std::int64_t count_conflicting_shared_vertices(std::span<const std::int32_t> shared_offsets,
                                               std::span<const std::int32_t> shared_members,
                                               std::span<const std::uint8_t> moving, const BoundaryMotion& motion);

}  // namespace dgwarp
