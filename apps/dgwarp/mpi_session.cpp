// mpi_session.hpp with MPI: the library's root-driven session and part plans
// (dgwarp/mpi/root_session.hpp) over MPI_COMM_WORLD.
#include <mpi.h>

#include <cstdlib>
#include <optional>
#include <string>

#include "dgwarp/core/error.hpp"
#include "dgwarp/core/parallel_for.hpp"
#include "distributed_run.hpp"
#include "dgwarp/mpi/root_session.hpp"
#include "mpi_session.hpp"

namespace dgwarp::cli {

namespace {

bool mpi_started = false;
int mpi_my_rank = 0, mpi_size = 1;
const MPI_Comm world = MPI_COMM_WORLD;

}  // namespace

int mpi_start(int& argc, char**& argv) {
    // Open MPI's mpirun sets OMPI_COMM_WORLD_SIZE in every process it starts;
    // without it, no MPI (a plain dgwarp starts as fast as without MPI).
    if (!std::getenv("OMPI_COMM_WORLD_SIZE") && !std::getenv("PMIX_RANK")) return 1;
    MPI_Init(&argc, &argv);
    mpi_started = true;
    MPI_Comm_rank(world, &mpi_my_rank);
    MPI_Comm_size(world, &mpi_size);
    // One thread per process unless --threads says otherwise (P processes
    // share the machine's cores).
    if (mpi_size > 1) set_num_threads(1);
    return mpi_size;
}

int mpi_rank() { return mpi_my_rank; }
int mpi_processes() { return mpi_size; }

void mpi_stop(int exit_code) {
    if (!mpi_started) return;
    if (mpi_my_rank == 0) mpi::root_stop(world, exit_code);
    MPI_Finalize();
    mpi_started = false;
}

int mpi_serve() { return mpi::serve_root(world, run_everywhere); }

void mpi_run_everywhere(const std::string& payload) { mpi::root_run_everywhere(world, payload); }

std::shared_ptr<DistributedRun> mpi_prepare_own(Method method, int dim, const MethodOptions& options,
                                                std::span<const double> points, std::span<const std::int64_t> global_ids,
                                                const BoundarySet& boundary, Plan& my_plan, std::vector<double>& seconds,
                                                std::int64_t& outside_hull) {
    auto run = std::make_shared<DistributedRun>();
    run->own = mpi::prepare_part(world, method, dim, points, global_ids, boundary, options);
    seconds = run->own->prepare_seconds;
    outside_hull = run->own->outside_hull;
    my_plan = run->own->plan.plan;
    return run;
}

std::shared_ptr<DistributedRun> mpi_prepare(const Mesh& mesh, const BoundarySet& boundary, Method method,
                                            const MethodOptions& options,
                                            const std::vector<std::vector<NodeId>>& node_parts, Plan& rank0_plan,
                                            std::vector<double>& seconds) {
    auto run = std::make_shared<DistributedRun>();
    run->root = mpi::root_prepare(world, mesh, boundary, method, options, node_parts, num_threads());
    rank0_plan = run->root->plan.plan.plan;
    seconds = run->root->plan.prepare_seconds;
    return run;
}

std::int64_t mpi_outside_hull(const DistributedRun& run) {
    return run.root ? run.root->plan.outside_hull : run.own ? run.own->outside_hull : 0;
}

StepReport mpi_deform(const DistributedRun& run, const BoundaryMotion& motion, std::span<double> out,
                      std::vector<double>& seconds) {
    return mpi::root_deform(*run.root, motion, out, seconds);
}

}  // namespace dgwarp::cli
