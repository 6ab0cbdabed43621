// The MPI test (registered with ctest, run with mpirun -np P): the distributed
// plan's deformed coordinates are the single-process run's, bit for bit, for
// every method named, with three partitions of the cells: contiguous blocks;
// round-robin, whose many interface nodes are held by several processes; and
// round-robin where only the lowest rank holding a boundary node lists it as
// one (the others hold it as a plain node and get its motion from that rank).
//
//   mpirun -np P mpi_same_bits MESH MOTION METHOD...
//
// METHOD: a method's name, or dg-idw-robust (continuous weights, auto length scale).
// Every process reads the mesh and the motion, computes the single-process
// result itself (the reference), holds the nodes of its cells (in the order
// its cells list them, not by global id) and compares its own nodes'
// coordinates after two steps (the motion's frame 0, then half of it).
// Exit 0 when every node of every process matches, 1 otherwise (rank 0
// prints the counts).
#include <mpi.h>

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <exception>
#include <string>
#include <vector>

#include "dgwarp/core/error.hpp"
#include "dgwarp/io/mesh_io.hpp"
#include "dgwarp/io/motion_file.hpp"
#include "dgwarp/motion/resolve_motion.hpp"
#include "dgwarp/mpi/distributed_plan.hpp"
#include "mesh_parts.hpp"

using namespace dgwarp;
using test::Part;
using test::Partition;
using test::make_part;
using test::partition_name;

namespace {

BoundaryMotion scaled(BoundaryMotion m, double s) {
    for (NodeMotion& x : m)
        for (int d = 0; d < 3; ++d) {
            x.translation[d] *= s;
            x.rotation[d] *= s;
        }
    return m;
}

}  // namespace

int main(int argc, char** argv) {
    MPI_Init(&argc, &argv);
    int rank = 0, size = 1;
    MPI_Comm_rank(MPI_COMM_WORLD, &rank);
    MPI_Comm_size(MPI_COMM_WORLD, &size);
    if (argc < 4) {
        if (rank == 0) std::fprintf(stderr, "usage: mpirun -np P %s MESH MOTION METHOD...\n", argv[0]);
        MPI_Finalize();
        return 2;
    }
    long long mismatches = 0, compared = 0;
    int failed = 0;
    try {
        const Mesh mesh = read_mesh(argv[1]);
        const MotionSpec spec = read_motion_file(argv[2]);
        const ResolvedBoundary resolved = resolve_boundary(mesh, spec);
        const BoundaryMotion motion = resolve_frame(mesh, spec, resolved, 0).motion;
        for (int a = 3; a < argc; ++a) {
            // "dg-idw-robust": DG-IDW with continuous weights and the auto length scale.
            const std::string name = argv[a];
            const bool robust = name == "dg-idw-robust";
            const Method method = robust ? Method::dg_idw : *method_from_name(name);
            // DGM sub-steps where the moved graph folds (the bricks' turned top face).
            MethodOptions options;
            options.dgm.on_invalid = DgmOptions::OnInvalidGraph::substep;
            if (robust) {
                options.dg_idw.weighting = DgIdwWeighting::continuous;
                options.dg_idw.length_scale = 0;  // auto: from the gap between moving and static boundary
            }
            const Plan serial = prepare(method, mesh.dim, mesh.points, resolved.boundary, options);
            for (Partition partition : {Partition::block, Partition::round_robin, Partition::round_robin_lowest_lists}) {
                const Part part = make_part(mesh, resolved.boundary, rank, size, partition);
                const mpi::DistributedPlan plan =
                    mpi::prepare_distributed(MPI_COMM_WORLD, method, mesh.dim, part.points, part.global_ids, part.boundary,
                                             options);
                for (double s : {1.0, 0.5}) {
                    const BoundaryMotion whole = scaled(motion, s);
                    std::vector<double> reference(mesh.points.size());
                    // A method that cannot produce a valid mesh (DGM's folded graph) must fail
                    // alike: the same error on every process.
                    std::int64_t serial_error = -1, distributed_error = -1;
                    StepReport r1, r2;
                    try {
                        r1 = deform(serial, mesh.points, whole, reference, options);
                    } catch (const InvalidResultError& e) {
                        serial_error = e.count();
                    }
                    BoundaryMotion mine(part.boundary.nodes.size());
                    for (std::size_t j = 0; j < mine.size(); ++j) mine[j] = whole[part.boundary_slot[j]];
                    std::vector<double> out(part.points.size());
                    try {
                        r2 = mpi::deform_distributed(plan, part.points, mine, out);
                    } catch (const InvalidResultError& e) {
                        distributed_error = e.count();
                    }
                    long long bad = 0;
                    if (serial_error < 0)
                        for (std::size_t i = 0; i < part.global_ids.size(); ++i)
                            bad += std::memcmp(out.data() + i * mesh.dim,
                                               reference.data() + static_cast<std::size_t>(part.global_ids[i]) * mesh.dim,
                                               sizeof(double) * mesh.dim) != 0;
                    if (serial_error != distributed_error || r1.conflicting_shared_vertices != r2.conflicting_shared_vertices ||
                        r1.substeps != r2.substeps || r1.rbf_centres != r2.rbf_centres)
                        ++bad;
                    long long all_bad = 0, all_nodes = 0, nodes = static_cast<long long>(part.global_ids.size());
                    MPI_Allreduce(&bad, &all_bad, 1, MPI_LONG_LONG, MPI_SUM, MPI_COMM_WORLD);
                    MPI_Allreduce(&nodes, &all_nodes, 1, MPI_LONG_LONG, MPI_SUM, MPI_COMM_WORLD);
                    if (rank == 0)
                        std::printf("%s P=%d %s partition, motion x%.1f: %lld of %lld process nodes differ "
                                    "(%lld boundary nodes, %lld coarse points)%s\n",
                                    argv[a], size, partition_name(partition), s, all_bad, all_nodes,
                                    static_cast<long long>(plan.num_boundary_nodes),
                                    static_cast<long long>(plan.num_coarse_points),
                                    serial_error >= 0 ? ", an invalid result on one process and on every process" : "");
                    mismatches += all_bad;
                    compared += all_nodes;
                }
            }
        }
    } catch (const std::exception& e) {
        std::fprintf(stderr, "process %d: %s\n", rank, e.what());
        failed = 1;
    }
    int any_failed = 0;
    MPI_Allreduce(&failed, &any_failed, 1, MPI_INT, MPI_MAX, MPI_COMM_WORLD);
    if (rank == 0 && !any_failed)
        std::printf("%s: %lld node coordinates compared, %lld differ from the single-process run\n",
                    mismatches == 0 ? "same bits" : "DIFFERENT", compared, mismatches);
    MPI_Finalize();
    return any_failed || mismatches != 0 ? 1 : 0;
}
