#pragma once
// A whole mesh split into the parts of P processes, for a program that holds
// the mesh on one process and deforms it on all (root_session.hpp; a solver
// brings its own partition and calls prepare_distributed directly). No MPI
// call: the split is the same on every process that makes it.
#include <cstdint>
#include <vector>

#include "dgwarp/mesh/mesh.hpp"
#include "dgwarp/methods/method.hpp"

namespace dgwarp::mpi {

/// What one process holds of the whole mesh.
struct NodePart {
    std::vector<std::int64_t> global_ids;  // its nodes (whole-mesh ids), in order of first use
    std::vector<double> points;            // their coordinates, global_ids.size() × dim
    BoundarySet boundary;                  // its boundary nodes (local indices, ascending), moving or not
    std::vector<std::int32_t> slots;       // per local boundary node: its index in the whole BoundarySet
};

/// Splits `mesh` into `parts` parts: part r holds the nodes of its block of
/// cells along a Morton curve (morton_cell_parts), or, when `node_parts` has
/// `parts` lists (a decomposed case's processors), the nodes of list r. A
/// node of several cells (or lists) of one part is held once by it, and by
/// every part with one of its cells; a node of none goes to part 0. Throws
/// MeshError for a boundary set that does not fit the mesh
/// (check_boundary_set) or a listed node out of range.
std::vector<NodePart> split_mesh(const Mesh& mesh, const BoundarySet& boundary, int parts,
                                 const std::vector<std::vector<NodeId>>& node_parts = {});

}  // namespace dgwarp::mpi
