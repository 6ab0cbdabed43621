// A flow solver's time loop on P processes (mpirun -np P solver_time_loop):
// each process holds a slab of the mesh, prepares the distributed plan once
// with the others, then every time step gives the motion of its own boundary
// nodes and gets the new coordinates of its own nodes (docs/MPI.md).
//
// The mesh: a 17^3 lattice on [-1, 1]^3 with a cubic hole |x|,|y|,|z| < 0.25
// (the body); the body pitches about the z axis and plunges along y, the outer
// faces stay. Process r holds the lattice planes k in [r K / P, (r+1) K / P]
// (K = 16): the planes between two slabs are held by both, as a partitioned
// solver's interface nodes are.
#include <mpi.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <vector>

#include "dgwarp/mpi/distributed_plan.hpp"

using namespace dgwarp;

int main(int argc, char** argv) {
    MPI_Init(&argc, &argv);
    int rank = 0, size = 1;
    MPI_Comm_rank(MPI_COMM_WORLD, &rank);
    MPI_Comm_size(MPI_COMM_WORLD, &size);

    // This process's nodes: coordinates, global ids (i + n (j + n k)), boundary.
    const int n = 17, k_planes = n - 1;
    const double h = 2.0 / k_planes, body = 0.25;
    const int k0 = rank * k_planes / size, k1 = (rank + 1) * k_planes / size;
    std::vector<double> x0;
    std::vector<std::int64_t> global_ids;
    BoundarySet boundary;  // sorted local indices, moving flags
    for (int k = k0; k <= k1; ++k)
        for (int j = 0; j < n; ++j)
            for (int i = 0; i < n; ++i) {
                const double p[3] = {-1 + i * h, -1 + j * h, -1 + k * h};
                const double r = std::max({std::abs(p[0]), std::abs(p[1]), std::abs(p[2])});
                if (r < body - 1e-12) continue;  // inside the body: not a mesh node
                const bool on_body = std::abs(r - body) < 1e-12, outer = std::abs(r - 1) < 1e-12;
                if (on_body || outer) {
                    boundary.nodes.push_back(static_cast<NodeId>(global_ids.size()));
                    boundary.moving.push_back(on_body);
                }
                global_ids.push_back(i + n * (j + static_cast<std::int64_t>(n) * k));
                x0.insert(x0.end(), p, p + 3);
            }

    // Prepare once (collective): DG-IDW, whose steps exchange only the motions each process needs.
    const mpi::DistributedPlan plan = mpi::prepare_distributed(MPI_COMM_WORLD, Method::dg_idw, 3, x0, global_ids, boundary);

    // The time loop: pitch (radians) and plunge of the body at each step.
    const int steps = 20;
    const double dt = 0.05, frequency = 1.0, pitch = 0.2, plunge = 0.05;
    BoundaryMotion motion(boundary.nodes.size());
    std::vector<double> x(x0.size());
    double max_seconds = 0, max_move = 0;
    for (int step = 0; step < steps; ++step) {
        const double phase = 2 * std::numbers::pi * frequency * step * dt;
        for (std::size_t b = 0; b < boundary.nodes.size(); ++b)
            if (boundary.moving[b])  // t, w (axis × angle), c
                motion[b] = {{0, plunge * std::sin(phase), 0}, {0, 0, pitch * std::sin(phase)}, {0, 0, 0}};
        const double t0 = MPI_Wtime();
        mpi::deform_distributed(plan, x0, motion, x);  // every node of x, measured from x0
        max_seconds = std::max(max_seconds, MPI_Wtime() - t0);
        for (std::size_t i = 0; i < x.size(); i += 3)
            max_move = std::max(max_move, std::hypot(x[i] - x0[i], x[i + 1] - x0[i + 1], x[i + 2] - x0[i + 2]));
    }
    // The figures of the whole mesh, on rank 0.
    double move = 0, seconds = 0;
    long long nodes = static_cast<long long>(global_ids.size()), all_nodes = 0;
    MPI_Reduce(&max_move, &move, 1, MPI_DOUBLE, MPI_MAX, 0, MPI_COMM_WORLD);
    MPI_Reduce(&max_seconds, &seconds, 1, MPI_DOUBLE, MPI_MAX, 0, MPI_COMM_WORLD);
    MPI_Reduce(&nodes, &all_nodes, 1, MPI_LONG_LONG, MPI_SUM, 0, MPI_COMM_WORLD);
    if (rank == 0)
        std::printf("%d processes, %lld process nodes (%lld boundary nodes, each counted once): %d steps, "
                    "largest node move %.4f, slowest step %.2f ms\n",
                    size, all_nodes, static_cast<long long>(plan.num_boundary_nodes), steps, move, seconds * 1e3);
    MPI_Finalize();
    return 0;
}
