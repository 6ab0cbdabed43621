#pragma once
// What processes holding parts of one mesh (a decomposed case, a solver's
// partition) agree on before a run, so that each classifies, judges and moves
// its nodes and cells as one process does over the whole mesh. Collective:
// every process of `comm` calls them, in the same order.
#include <mpi.h>

#include <cstdint>
#include <span>
#include <vector>

#include "dgwarp/mesh/mesh.hpp"

namespace dgwarp::mpi {

/// Nodes held by several processes (`interface`: local nodes, each process
/// its own) may be on different markers on each: a node on the edge of a
/// marker whose faces are all on another process. Adds to each of `mesh`'s
/// markers, as vertex elements, the interface nodes another process has on
/// the marker of the same index (every process has the same markers in the
/// same order), so that resolve_boundary classifies them alike everywhere.
/// `global_ids`: per local node, its id in the whole mesh. Returns per local
/// node whether this process owns it: the lowest rank holding it (nodes
/// not in `interface` are owned).
std::vector<std::uint8_t> share_interface_markers(MPI_Comm comm, Mesh& mesh, std::span<const NodeId> interface,
                                                  std::span<const std::int64_t> global_ids);

/// The bounding-box diagonal of every process's points: what
/// resolve_boundary takes over the whole mesh (its shared-node tolerance is
/// 1e-9 times it).
double bounding_box_diagonal_over_parts(MPI_Comm comm, const Mesh& mesh);

/// dominant_orientations over every process's cells: per local cell, the
/// orientation of the majority of its type's cells over the whole mesh.
/// `own`: each local cell's own orientation (cell_orientations).
std::vector<std::int8_t> dominant_orientations_over_parts(MPI_Comm comm, const Mesh& mesh,
                                                          std::span<const std::int8_t> own);

}  // namespace dgwarp::mpi
