// Strong scaling of the distributed plans (docs/MPI.md), a benchmark, not a
// test (the suite runs it once on a small mesh to keep it working):
//
//   mpirun -np P mpi_scaling MESH MOTION METHOD [STEPS]
//
// Every process reads the mesh, holds the nodes of a block of cells along a
// Morton curve (as `mpirun dgwarp deform` gives them), prepares and runs STEPS steps (default
// 20) of the motion's frame 0. Rank 0 prints, as the maximum over the
// processes: prepare and its phases, the median step, the plan's bytes and
// the peak resident memory per process; and the graph-broadcast measurement:
// the time to broadcast from rank 0 an array the size of the Delaunay graph
// (its simplices and their neighbours, int32), against building it on every
// process.
#include <mpi.h>
#include <sys/resource.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "dgwarp/io/mesh_io.hpp"
#include "dgwarp/io/motion_file.hpp"
#include "dgwarp/motion/resolve_motion.hpp"
#include "dgwarp/mpi/distributed_plan.hpp"
#include "dgwarp/mpi/morton_partition.hpp"

using namespace dgwarp;

namespace {

double max_over(double x) {
    double m = 0;
    MPI_Allreduce(&x, &m, 1, MPI_DOUBLE, MPI_MAX, MPI_COMM_WORLD);
    return m;
}

double peak_rss_mb() {
    rusage u{};
    getrusage(RUSAGE_SELF, &u);
    return static_cast<double>(u.ru_maxrss) / 1024.0;  // Linux: kilobytes
}

}  // namespace

int main(int argc, char** argv) {
    MPI_Init(&argc, &argv);
    int rank = 0, size = 1;
    MPI_Comm_rank(MPI_COMM_WORLD, &rank);
    MPI_Comm_size(MPI_COMM_WORLD, &size);
    if (argc < 4) {
        if (rank == 0) std::fprintf(stderr, "usage: mpirun -np P %s MESH MOTION METHOD [STEPS]\n", argv[0]);
        MPI_Finalize();
        return 2;
    }
    const int steps = argc > 4 ? std::atoi(argv[4]) : 20;
    const Method method = *method_from_name(argv[3]);
    const Mesh mesh = read_mesh(argv[1]);
    const MotionSpec spec = read_motion_file(argv[2]);
    const ResolvedBoundary resolved = resolve_boundary(mesh, spec);
    const BoundaryMotion whole = resolve_frame(mesh, spec, resolved, 0).motion;
    const double rss_mesh = max_over(peak_rss_mb());

    // This process's part: the nodes of its cells, in first-use order.
    const std::size_t cells = mesh.cells.types.size();
    std::vector<std::int32_t> local(mesh.num_points(), -1), slot(mesh.num_points(), -1);
    for (std::size_t b = 0; b < resolved.boundary.nodes.size(); ++b) slot[resolved.boundary.nodes[b]] = static_cast<std::int32_t>(b);
    std::vector<double> points;
    std::vector<std::int64_t> ids;
    BoundarySet boundary;
    BoundaryMotion motion;
    const std::vector<std::int32_t> cell_part = mpi::morton_cell_parts(mesh, size);
    for (std::size_t c = 0; c < cells; ++c)
        if (cell_part[c] == rank)
        for (std::int64_t k = mesh.cells.offsets[c]; k < mesh.cells.offsets[c + 1]; ++k) {
            const NodeId n = mesh.cells.nodes[k];
            if (local[n] >= 0) continue;
            local[n] = static_cast<std::int32_t>(ids.size());
            if (slot[n] >= 0) {
                boundary.nodes.push_back(local[n]);
                boundary.moving.push_back(resolved.boundary.moving[slot[n]]);
                motion.push_back(whole[slot[n]]);
            }
            ids.push_back(n);
            for (int d = 0; d < mesh.dim; ++d) points.push_back(mesh.points[static_cast<std::size_t>(n) * mesh.dim + d]);
        }

    MPI_Barrier(MPI_COMM_WORLD);
    double t0 = MPI_Wtime();
    const mpi::DistributedPlan plan = mpi::prepare_distributed(MPI_COMM_WORLD, method, mesh.dim, points, ids, boundary);
    const double prepare = max_over(MPI_Wtime() - t0);
    const double rss_plan = max_over(peak_rss_mb());
    std::vector<double> out(points.size()), times;
    for (int s = 0; s < steps; ++s) {
        MPI_Barrier(MPI_COMM_WORLD);
        t0 = MPI_Wtime();
        mpi::deform_distributed(plan, points, motion, out);
        times.push_back(max_over(MPI_Wtime() - t0));
    }
    std::sort(times.begin(), times.end());
    const double step = times[times.size() / 2];
    const PlanSummary summary = plan_summary(plan.plan);
    const std::int64_t simplices = summary.graph_simplices.value_or(0);

    // A graph built on rank 0 and broadcast: its simplices and their
    // neighbours ((dim + 1) int32 each), the least a process would need to
    // locate its nodes without building the graph itself.
    std::vector<std::int32_t> graph(static_cast<std::size_t>(simplices) * 2 * (mesh.dim + 1), rank);
    MPI_Barrier(MPI_COMM_WORLD);
    t0 = MPI_Wtime();
    MPI_Bcast(graph.data(), static_cast<int>(graph.size()), MPI_INT32_T, 0, MPI_COMM_WORLD);
    const double broadcast = max_over(MPI_Wtime() - t0);
    double graph_seconds = 0;
    for (const auto& [phase, s] : summary.phase_seconds)
        if (phase == "graph") graph_seconds = s;
    graph_seconds = max_over(graph_seconds);
    const double local_nodes = max_over(static_cast<double>(ids.size()));
    const double bytes = max_over(static_cast<double>(mpi::distributed_plan_bytes(plan)));
    // Motions a process receives per step (DG-IDW: those it needs; the others: every moving one).
    const double received = max_over(static_cast<double>(plan.gather_all ? plan.owned_boundary.size()
                                                                         : plan.recv_boundary.size()));
    const double gather = max_over(plan.times.gather_seconds), coarse = max_over(plan.times.coarse_seconds),
                 method_s = max_over(plan.times.method_seconds);
    if (rank == 0)
        std::printf("P=%d %s nodes %zu (at most %.0f on a process) boundary %lld: prepare %.3f s (gather %.3f, coarse %.3f, method %.3f, of which "
                    "graph %.3f), step median %.2f ms (of %d), plan %.1f MB/process, peak RSS %.0f MB/process (%.0f MB "
                    "after reading the mesh), motions received per step %.0f (%.2f MB), graph broadcast %.4f s for %.1f MB\n",
                    size, argv[3], mesh.num_points(), local_nodes, static_cast<long long>(plan.num_boundary_nodes), prepare, gather,
                    coarse, method_s, graph_seconds, step * 1e3, steps, bytes / 1e6, rss_plan, rss_mesh, received,
                    received * sizeof(NodeMotion) / 1e6, broadcast,
                    static_cast<double>(graph.size()) * 4 / 1e6);
    MPI_Finalize();
    return 0;
}
