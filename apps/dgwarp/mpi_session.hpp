#pragma once
// The CLI's MPI (docs/MPI.md), over MPI_COMM_WORLD: the library's
// root-driven session (dgwarp/mpi/root_session.hpp: `mpirun -np P dgwarp
// deform MESH -m MOTION -o OUT` has rank 0 run the command as one process
// would, the prepare and steps on every process), its part plans,
// agreement and reductions. On a decomposed OpenFOAM case of P processor
// folders, rank 0 instead has every process run the command on its own
// folder (mpi_run_everywhere, deform_processors.hpp).
//
// Built with MPI: mpi_session.cpp, which forwards to dgwarp/mpi, and the
// per-processor run (deform_processors.cpp); without:
// mpi_session_serial.cpp (one process; started by mpirun with several, it
// refuses to run, rather than have P copies write the same files).
#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "dgwarp/mesh/mesh.hpp"
#include "dgwarp/methods/method.hpp"

namespace dgwarp::cli {

/// A distributed deformation (its plans on every process).
struct DistributedRun;

/// Starts MPI when this process was started by mpirun (else nothing).
/// Returns the number of processes (1 without mpirun).
int mpi_start(int& argc, char**& argv);

/// This process's rank (0 without mpirun).
int mpi_rank();

/// The number of processes (1 without mpirun).
int mpi_processes();

/// Ranks > 0: serve rank 0's prepares and steps until it stops (mpi_stop).
/// Returns the exit code of the last run every process made
/// (mpi_run_everywhere): 0, or the exit code of its error.
int mpi_serve();

/// Rank 0: has every other process call `run_everywhere(payload)`
/// (deform_processors.hpp) now, and returns: rank 0 then makes the same call.
/// For the runs where every process reads and writes its own part.
void mpi_run_everywhere(const std::string& payload);
/// Ranks > 0, from mpi_serve: the run rank 0 started; returns its exit code.
int run_everywhere(const std::string& payload);

/// Every process: prepares `method` over this process's own nodes (points,
/// global ids, boundary), collectively; `my_plan`: this process's plan (over
/// its working nodes), `seconds` (rank 0): each process's prepare time,
/// `outside_hull`: the volume nodes outside the graph's hull, summed over the processes.
std::shared_ptr<DistributedRun> mpi_prepare_own(Method method, int dim, const MethodOptions& options,
                                                std::span<const double> points, std::span<const std::int64_t> global_ids,
                                                const BoundarySet& boundary, Plan& my_plan, std::vector<double>& seconds,
                                                std::int64_t& outside_hull);

/// Rank 0: tells the other ranks to stop, with its exit code (mpi_serve
/// returns it, so every rank exits with it); every rank: ends MPI.
void mpi_stop(int exit_code = 0);

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
