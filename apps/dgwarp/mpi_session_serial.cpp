// mpi_session.hpp without MPI (dgwarp built without Open MPI): one process.
#include <cstdlib>
#include <string>

#include "dgwarp/core/error.hpp"
#include "deform_processors.hpp"
#include "mpi_session.hpp"

namespace dgwarp::cli {

struct DistributedRun {};

int mpi_start(int&, char**&) {
    // Open MPI's mpirun sets OMPI_COMM_WORLD_SIZE in every process it starts.
    if (const char* size = std::getenv("OMPI_COMM_WORLD_SIZE"); size && std::atoi(size) > 1)
        throw Error("this dgwarp was built without MPI, but mpirun started " + std::string(size) +
                    " copies of it: install libopenmpi-dev (scripts/install-deps.sh) and build again, or run "
                    "one dgwarp without mpirun");
    return 1;
}
int mpi_rank() { return 0; }
int mpi_processes() { return 1; }
int mpi_serve() { return 0; }
void mpi_run_everywhere(const std::string&) {}
int run_everywhere(const std::string&) { throw Error("run_everywhere: dgwarp was built without MPI"); }

// deform_processors.hpp: each process its own processor folder needs several processes.
bool deforms_per_processor(const DeformArgs&, const std::vector<Method>&) { return false; }
void run_deform_per_processor(const DeformArgs&, const std::string&) {
    throw Error("run_deform_per_processor: dgwarp was built without MPI");
}
void mpi_stop(int) {}

std::shared_ptr<DistributedRun> mpi_prepare(const Mesh&, const BoundarySet&, Method, const MethodOptions&,
                                            const std::vector<std::vector<NodeId>>&, Plan&, std::vector<double>&) {
    throw Error("mpi_prepare: dgwarp was built without MPI");
}

std::int64_t mpi_outside_hull(const DistributedRun&) { return 0; }

StepReport mpi_deform(const DistributedRun&, const BoundaryMotion&, std::span<double>, std::vector<double>&) {
    throw Error("mpi_deform: dgwarp was built without MPI");
}

}  // namespace dgwarp::cli
