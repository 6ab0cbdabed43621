#include "dgwarp/mpi/collective_checks.hpp"

#include "dgwarp/core/error.hpp"

namespace dgwarp::mpi::detail {

void throw_if_any_failed(MPI_Comm comm, const std::string& local_error, const std::string& what) {
    int rank = 0, size = 1;
    MPI_Comm_rank(comm, &rank);
    MPI_Comm_size(comm, &size);
    const int mine = local_error.empty() ? size : rank;
    int first = size;
    MPI_Allreduce(&mine, &first, 1, MPI_INT, MPI_MIN, comm);
    if (first == size) return;
    if (!local_error.empty()) throw MeshError("process " + std::to_string(rank) + ": " + local_error);
    throw Error("process " + std::to_string(first) + " refused " + what + " (its own error message says why)");
}

}  // namespace dgwarp::mpi::detail
