#include "dgwarp/mpi/collective_checks.hpp"

#include "dgwarp/core/error.hpp"

namespace dgwarp::mpi::detail {

void throw_if_any_failed(MPI_Comm comm, const std::string& local_error, const std::string& what,
                         bool invalid_result) {
    int rank = 0, size = 1;
    MPI_Comm_rank(comm, &rank);
    MPI_Comm_size(comm, &size);
    const int mine = local_error.empty() ? size : rank;
    int first = size;
    MPI_Allreduce(&mine, &first, 1, MPI_INT, MPI_MIN, comm);
    if (first == size) return;
    std::string message = !local_error.empty() ? "process " + std::to_string(rank) + ": " + local_error
                                               : "process " + std::to_string(first) + " refused " + what +
                                                     " (its own error message says why)";
    if (invalid_result) throw InvalidResultError(message, 1);
    if (!local_error.empty()) throw MeshError(message);
    throw Error(message);
}

}  // namespace dgwarp::mpi::detail
