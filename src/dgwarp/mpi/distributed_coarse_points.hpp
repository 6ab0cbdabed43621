#pragma once
// Internal: DG-harmonic's coarse points selected over the volume nodes of
// every process (coarse_points.hpp's three stages), the same on every process
// and the same as select_coarse_points on the whole mesh.
#include <mpi.h>

#include <cstdint>
#include <span>
#include <vector>

#include "dgwarp/methods/coarse_points.hpp"

namespace dgwarp::mpi::detail {

struct CoarsePoints {
    std::vector<std::int64_t> global_ids;  // ascending
    std::vector<double> points;            // num × dim
};

/// Collective. points: this process's working points (num × dim) where
/// `boundary_nodes` are every boundary node of the mesh and `volume_nodes`
/// this process's volume nodes, ascending in global id (volume_global_ids).
CoarsePoints select_coarse_points_distributed(MPI_Comm comm, int dim, std::span<const double> points,
                                              std::span<const NodeId> boundary_nodes,
                                              std::span<const NodeId> volume_nodes,
                                              std::span<const std::int64_t> volume_global_ids,
                                              const CoarseSpacing& spacing);

}  // namespace dgwarp::mpi::detail
