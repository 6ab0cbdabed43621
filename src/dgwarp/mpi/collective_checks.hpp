#pragma once
// Internal: errors found on one process, raised on every process, so that no
// process waits forever in a collective call the failing one never makes.
#include <mpi.h>

#include <string>

namespace dgwarp::mpi::detail {

/// Collective over `comm`: when any process has a non-empty `local_error`,
/// throws on every process: MeshError(local_error) where it was found, and an
/// Error naming the lowest such rank and `what` on the others; with
/// `invalid_result`, InvalidResultError on every process instead (exit code 3
/// in the CLI, as one process's).
void throw_if_any_failed(MPI_Comm comm, const std::string& local_error, const std::string& what,
                         bool invalid_result = false);

}  // namespace dgwarp::mpi::detail
