// mpi_session.hpp without MPI (dgwarp built without Open MPI): one process.
#include <cstdlib>
#include <string>

#include "dgwarp/core/error.hpp"
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
void mpi_serve() {}
void mpi_stop() {}

std::shared_ptr<DistributedRun> mpi_prepare(const Mesh&, const BoundarySet&, Method, const MethodOptions&,
                                            const std::vector<std::vector<NodeId>>&, Plan&, std::vector<double>&) {
    throw Error("mpi_prepare: dgwarp was built without MPI");
}

std::int64_t mpi_outside_hull(const DistributedRun&) { return 0; }

StepReport mpi_deform(const DistributedRun&, const BoundaryMotion&, std::span<double>, std::vector<double>&) {
    throw Error("mpi_deform: dgwarp was built without MPI");
}

}  // namespace dgwarp::cli
