#pragma once
// A deformation driven by one process: the root (rank 0 of `comm`) holds the
// whole mesh, as a program that reads one file does (the CLI under mpirun);
// the prepare and every step run on every process with the distributed plans
// (distributed_plan.hpp). The root splits the mesh (split_mesh), hands each
// process its part and, every step, its boundary motions, and gathers the new
// coordinates; the other processes serve it (serve_root) until it stops them.
//
//   if (rank == 0) {
//       RootRun run = root_prepare(comm, mesh, boundary, Method::dg_idw);
//       root_deform(comm, run, motion, out, seconds);   // as often as needed
//       root_stop(comm, 0);
//   } else {
//       code = serve_root(comm, {});
//   }
//
// Where each process holds a part of its own (a solver's partition, a
// decomposed case), prepare_part and deform_part give the same plans and
// steps with their timings, without a root.
#include <mpi.h>

#include <cstdint>
#include <functional>
#include <span>
#include <string>
#include <vector>

#include "dgwarp/mesh/mesh.hpp"
#include "dgwarp/methods/method.hpp"
#include "dgwarp/mpi/distributed_plan.hpp"
#include "dgwarp/mpi/mesh_parts.hpp"

namespace dgwarp::mpi {

/// A distributed plan with what a run reports of its prepare.
struct PartPlan {
    DistributedPlan plan;
    std::vector<double> prepare_seconds;  // on rank 0: each process's prepare time (empty elsewhere)
    std::int64_t outside_hull = 0;        // volume nodes outside the graph's hull, summed over the processes
};

/// Collective: prepare_distributed over this process's own part, timed
/// (outside_hull on every process). Throws on every process alike.
PartPlan prepare_part(MPI_Comm comm, Method method, int dim, std::span<const double> points,
                      std::span<const std::int64_t> global_ids, const BoundarySet& boundary,
                      const MethodOptions& options = {});

/// Collective: deform_distributed over this process's part; `seconds` (rank
/// 0): each process's step time.
StepReport deform_part(const PartPlan& plan, std::span<const double> points, const BoundaryMotion& motion,
                       std::span<double> out, std::vector<double>& seconds);

/// The root's side of a distributed deformation.
struct RootRun {
    MPI_Comm comm = MPI_COMM_NULL;
    int dim = 3;
    std::vector<NodePart> parts;  // per rank (the root's too)
    PartPlan plan;                // the root's; plan.plan.plan is its plan over its working nodes
};

/// The root: splits the mesh (split_mesh with `node_parts`), has every
/// process prepare `method` over its part with `threads` threads (0: each
/// its own setting), and returns the run. Throws on every process alike
/// (the other processes' serve_root goes on waiting for the next command).
RootRun root_prepare(MPI_Comm comm, const Mesh& mesh, const BoundarySet& boundary, Method method,
                     const MethodOptions& options = {}, const std::vector<std::vector<NodeId>>& node_parts = {},
                     int threads = 0);

/// The root: one step on every process; `motion`: one per node of the whole
/// BoundarySet; writes every node's new coordinates to `out` (num_points ×
/// dim). `seconds`: each process's step time. Throws on every process alike.
StepReport root_deform(const RootRun& run, const BoundaryMotion& motion, std::span<double> out,
                       std::vector<double>& seconds);

/// The root: has every other process call serve_root's `run_payload(payload)`
/// now (the root then makes its own call): for runs where each process
/// reads and writes its own part.
void root_run_everywhere(MPI_Comm comm, const std::string& payload);

/// The root: tells the other processes to stop; their serve_root returns
/// `exit_code` when it is not 0, else the code of their last run_payload.
void root_stop(MPI_Comm comm, int exit_code);

/// Every process but the root: serves the root's prepares, steps and
/// payloads until root_stop. Errors of a prepare or step are raised on the
/// root too, which reports them; serve_root waits for the next command.
int serve_root(MPI_Comm comm, const std::function<int(const std::string& payload)>& run_payload);

}  // namespace dgwarp::mpi
