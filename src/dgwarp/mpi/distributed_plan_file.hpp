#pragma once
// A distributed plan on disk (docs/MPI.md, "Plans on disk"): every process's
// plan in one file, so that a partitioned solver prepares once and later runs
// load it with the same partition. Format (version 1, little-endian): magic
// "DGWDIST\0", u32 version, u32 number of processes P, then per process (in
// rank order) a u64 length and its part; a trailing u64 checksum (hash64
// chained over the header and the parts). A part: its rank, the method, the
// dimension, its counts, a hash of the process's inputs (points, global ids,
// boundary nodes and flags), the arrays of DistributedPlan and the method's
// plan file (plan/plan_file.hpp: dg-idw and dg-harmonic plans can be saved).
#include <mpi.h>

#include <cstdint>
#include <filesystem>
#include <span>

#include "dgwarp/mpi/distributed_plan.hpp"

namespace dgwarp::mpi {

/// Collective: process 0 gathers every process's part and writes `path`
/// atomically. Throws Error for a method whose plans cannot be saved (on
/// every process), IoError on process 0 when the file cannot be written (and
/// an Error saying so on the others).
void save_distributed_plan(const std::filesystem::path& path, const DistributedPlan& plan);

/// Collective: process 0 reads `path` and sends each process its part, which
/// it checks against its inputs (as prepare_distributed's). Every failure is
/// raised on every process: IoError / ParseError (damaged file, another
/// version, another number of processes) on process 0 and an Error naming it
/// on the others; MeshError on a process whose points, global ids or
/// boundary are not those the plan was prepared with, an Error elsewhere.
DistributedPlan load_distributed_plan(MPI_Comm comm, const std::filesystem::path& path,
                                      std::span<const double> points, std::span<const std::int64_t> global_ids,
                                      const BoundarySet& boundary);

/// The hash DistributedPlan::input_hash keeps of a process's inputs.
std::uint64_t distributed_inputs_hash(std::span<const double> points, std::span<const std::int64_t> global_ids,
                                      const BoundarySet& boundary);

}  // namespace dgwarp::mpi
