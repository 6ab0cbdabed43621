#pragma once
// `mpirun -np P dgwarp deform MESH -m MOTION -o OUT` (docs/MPI.md): rank 0
// runs the command as one process would (reads, checks, measures, writes,
// reports); the deformation's prepare and steps run on every process with the
// distributed plans of dgwarp/mpi. Rank 0 gives each process the nodes of a
// block of cells and, every step, their boundary motions, and gathers their
// new coordinates. The other ranks only serve rank 0 (mpi_serve).
//
// Built with MPI: mpi_session.cpp; without: mpi_session_serial.cpp (one
// process; started by mpirun with several, it refuses to run, rather than
// have P copies write the same files).
#include <cstdint>
#include <memory>
#include <span>
#include <vector>

#include "dgwarp/mesh/mesh.hpp"
#include "dgwarp/methods/method.hpp"

namespace dgwarp::cli {

/// Starts MPI when this process was started by mpirun (else nothing).
/// Returns the number of processes (1 without mpirun).
int mpi_start(int& argc, char**& argv);

/// This process's rank (0 without mpirun).
int mpi_rank();

/// The number of processes (1 without mpirun).
int mpi_processes();

/// Ranks > 0: serve rank 0's prepares and steps until it stops (mpi_stop).
void mpi_serve();

/// Rank 0: tells the other ranks to stop; every rank: ends MPI.
void mpi_stop();

/// A distributed deformation run from rank 0.
struct DistributedRun;

/// Rank 0: prepares `method` on every process, each with the nodes of its
/// block of cells along a Morton curve, or, when `node_parts` has one list
/// per process (a decomposed OpenFOAM case's processors), the nodes of its
/// list. `rank0_plan`: rank 0's own plan (over its working nodes: the
/// whole boundary and its own volume nodes). `seconds`: each process's
/// prepare time. Throws as prepare does.
std::shared_ptr<DistributedRun> mpi_prepare(const Mesh& mesh, const BoundarySet& boundary, Method method,
                                            const MethodOptions& options,
                                            const std::vector<std::vector<NodeId>>& node_parts, Plan& rank0_plan,
                                            std::vector<double>& seconds);

/// Rank 0: the volume nodes outside the graph's hull, summed over the
/// processes (a node held by several processes counts once for each).
std::int64_t mpi_outside_hull(const DistributedRun& run);

/// Rank 0: one step on every process; `motion` one NodeMotion per node of
/// the whole BoundarySet; writes every node's new coordinates to `out`
/// (num_points × dim). `seconds`: each process's step time.
StepReport mpi_deform(const DistributedRun& run, const BoundaryMotion& motion, std::span<double> out,
                      std::vector<double>& seconds);

}  // namespace dgwarp::cli
