#pragma once
// Internal: the boundary nodes of every process, gathered to every process
// and each counted once (prepare_distributed's first phase).
#include <mpi.h>

#include <cstdint>
#include <span>
#include <vector>

#include "dgwarp/motion/node_motion.hpp"

namespace dgwarp::mpi::detail {

struct GatheredBoundary {
    std::vector<std::int64_t> global_ids;  // ascending, unique: boundary index b is a position here
    std::vector<std::uint8_t> moving;      // per boundary index
    std::vector<double> points;            // num × dim
    std::vector<std::int32_t> owner;       // per boundary index: the lowest rank holding it
    std::vector<std::int32_t> local_index; // per local boundary node (BoundarySet order): its boundary index
};

/// Collective. Throws (on every process) MeshError when processes disagree on
/// a boundary node's coordinates or moving flag (naming its global id).
GatheredBoundary gather_boundary(MPI_Comm comm, int dim, std::span<const double> points,
                                 std::span<const std::int64_t> global_ids, const BoundarySet& boundary);

}  // namespace dgwarp::mpi::detail
