#pragma once
// Errors agreed between processes: each process runs a phase of its own
// (reading its part, preparing, stepping), then every process learns whether
// any failed, and every process throws the same error together, so that no
// process waits forever in a collective call the failing one never makes.
//
//   mpi::collectively(comm, [&] { part = read_my_part(file); });
//   // here every process read its part, or every process has thrown
#include <mpi.h>

#include <cstdint>
#include <exception>

namespace dgwarp::mpi {

/// Collective over `comm`: every process calls it after a phase, with the
/// phase's error on this process (or none). When no process failed, returns.
/// Else every process throws the error of the lowest failing rank: that rank
/// rethrows its own exception; the others throw one of the same kind
/// (UsageError, InvalidResultError with its count, Error for every other
/// dgwarp::Error, std::runtime_error for any other exception, a bad_alloc
/// included) with its message prefixed by "process r: ".
void agree(MPI_Comm comm, const std::exception_ptr& error);

/// Runs `phase` on this process, then agrees with the others (agree): every
/// process goes on, or every process throws the first failure.
template <class F>
void collectively(MPI_Comm comm, F&& phase) {
    std::exception_ptr error;
    try {
        phase();
    } catch (...) {
        error = std::current_exception();
    }
    agree(comm, error);
}

}  // namespace dgwarp::mpi
