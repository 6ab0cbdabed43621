#pragma once
// Mesh deformation inside an MPI solver: every process holds a part of the
// mesh (its own nodes, with their global ids), prepares once with the other
// processes, and every step gives the motions of its own boundary nodes and
// gets the new coordinates of its own nodes (docs/MPI.md). The deformed
// coordinates are the single-process run's, bit for bit, whatever the number
// of processes and the partition.
//
//   DistributedPlan plan = prepare_distributed(comm, Method::dg_idw, dim, points, global_ids, boundary);
//   for (step ...) deform_distributed(plan, points, motion, out);
//
// Conventions, per process: points num_local × dim row-major; global_ids one
// per local node: its 0-based id in the whole mesh (the single-process run's
// node numbering: its results are reproduced). A node on a partition interface
// is held by several processes, with the same global id (and the same
// coordinates). `boundary` is a BoundarySet over the local nodes (sorted
// local indices and a moving flag each, from the markers as for one process:
// motion/marker_node_motions.hpp); `motion` one NodeMotion per local boundary
// node in that order. A boundary node held by several processes has the same
// coordinates and flag on each that lists it as a boundary node, and moves
// with its owner's motion (the lowest rank listing it) on every one, whatever
// motion the others give their copies (every method; tested); a
// process may hold it as a plain node (a partition interface node whose
// boundary faces are all on another process): it then moves with the motion
// of a process that lists it.
//
// What is replicated (on every process) and what is exchanged:
//  * prepare gathers the boundary nodes (each counted once, whichever
//    processes hold it) to every process, which builds the method's graph
//    (the Delaunay graph of the boundary nodes, replicated: measured against
//    building it on one process and broadcasting it in docs/MPI.md) and
//    locates only its own volume nodes in it;
//  * DG-IDW: each step, a process receives only the motions of the boundary
//    nodes its volume nodes' graph simplices have as moving corners (from the
//    process owning each: the lowest rank holding it), and one max reduction
//    (the largest rotation angle, which sets the rotation's Taylor terms);
//  * DG-harmonic, IDW, RBF, DGM: every step gathers every moving boundary
//    node's motion to every process (allgather; static nodes' motions are
//    zero, as for one process, and not sent): DG-harmonic's coarse harmonic solve
//    couples all boundary nodes (the coarse level, a few percent of the
//    nodes, is selected over all processes and then replicated), IDW and RBF
//    sum over every boundary node (centre), and DGM's graph check moves the
//    whole graph.
#include <mpi.h>

#include <cstdint>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "dgwarp/methods/method.hpp"

namespace dgwarp::mpi {

/// Seconds of prepare's phases on this process.
struct DistributedPrepareTimes {
    double gather_seconds = 0;    // boundary nodes gathered and deduplicated
    double coarse_seconds = 0;    // DG-harmonic: coarse points selected over the processes
    double method_seconds = 0;    // the method's prepare (graph, location, weights, factorisation)
    double exchange_seconds = 0;  // DG-IDW: which motions each process sends to which
};

/// A process's plan: the method's plan over its "working nodes" (every
/// boundary node of the whole mesh, in global id order, then DG-harmonic's
/// coarse points, then its own volume nodes; DG-IDW keeps only the boundary
/// nodes its step reads: its own and the moving corners of its volume nodes'
/// graph simplices) and what each step exchanges.
/// Keeps `comm` (the caller keeps it alive for the plan's life).
struct DistributedPlan {
    MPI_Comm comm = MPI_COMM_NULL;
    int rank = 0, size = 1;
    Method method = Method::dg_idw;
    int dim = 3;
    std::int64_t num_local_points = 0;
    std::int64_t num_boundary_nodes = 0;  // of the whole mesh, each counted once
    std::int64_t num_coarse_points = 0;   // DG-harmonic: coarse volume nodes of the whole mesh
    MethodOptions options;
    Plan plan;                             // over the working nodes
    std::vector<double> working_points;    // num_working × dim
    std::vector<std::int32_t> local_to_working;  // per local node
    std::vector<std::int32_t> local_boundary_index;  // per local boundary node: its working boundary index
    /// Working boundary indices of the local nodes not in `boundary` that
    /// another process lists as boundary nodes (their motions come from it).
    std::vector<std::int32_t> adopted_boundary;
    /// Gather-all methods: the global boundary indices whose motions each
    /// process contributes (the moving ones it owns; a static node's motion
    /// is zero and never sent), concatenated by rank; owned_counts[r] entries each.
    bool gather_all = false;
    std::vector<int> owned_counts;
    std::vector<std::int32_t> owned_boundary;  // by rank, ascending within a rank
    std::vector<std::int32_t> my_owned_local;  // this process's owned ones, as local boundary indices
    /// DG-IDW: motions sent per step. send_local: local boundary indices, by
    /// destination rank (send_counts entries each); recv_boundary: global
    /// working boundary indices received, by source rank (recv_counts each).
    std::vector<int> send_counts, recv_counts;
    std::vector<std::int32_t> send_local, recv_boundary;
    /// DG-IDW: the shared graph vertices this process counts in the step
    /// report (those whose first boundary node it owns), as working boundary indices.
    std::vector<std::int32_t> counted_shared_offsets{0}, counted_shared_members;
    DistributedPrepareTimes times;
    /// A hash of this process's inputs to prepare (points, global ids,
    /// boundary): a saved plan is loaded only for the same ones.
    std::uint64_t input_hash = 0;

    std::int64_t num_working_points() const {
        return static_cast<std::int64_t>(working_points.size()) / dim;
    }
};

/// Prepares `method` for the whole mesh, collectively over `comm` (every
/// process calls it). Every failure is collective: the method, dimension and
/// options are compared with process 0's before anything else, the inputs
/// checked (sizes, ids, finite coordinates), and an exception of the method's
/// local prepare raised on every process; no process is left waiting in a
/// collective call. Throws MeshError on this process's bad input (sizes,
/// unsorted boundary, a boundary node whose coordinates or flag differ
/// between processes, naming its global id, or a plain node at other
/// coordinates than the boundary node of the same id) and on every other process an
/// Error saying which process refused its input; otherwise as the method's
/// prepare on one process.
DistributedPlan prepare_distributed(MPI_Comm comm, Method method, int dim, std::span<const double> points,
                                    std::span<const std::int64_t> global_ids, const BoundarySet& boundary,
                                    const MethodOptions& options = {});

/// One step, collectively: writes the new coordinates of this process's
/// nodes to `out` (num_local × dim; may alias `points`). The report is the
/// whole mesh's (the same on every process). Throws MeshError for a size
/// mismatch (on every process: sizes are checked collectively).
StepReport deform_distributed(const DistributedPlan& plan, std::span<const double> points,
                              const BoundaryMotion& motion, std::span<double> out);

/// Bytes this process holds for the plan (the method's plan, the working
/// points, the exchange lists).
std::size_t distributed_plan_bytes(const DistributedPlan& plan);

/// Whether `method` exchanges only the motions each process needs (DG-IDW)
/// or gathers every boundary motion every step (the others).
bool gathers_all_motions(Method method);

}  // namespace dgwarp::mpi
