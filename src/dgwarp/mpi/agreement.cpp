// agreement.hpp: the lowest failing rank's error, on every process.
#include "dgwarp/mpi/agreement.hpp"

#include <new>
#include <stdexcept>
#include <string>

#include "dgwarp/core/error.hpp"
#include "dgwarp/mpi/reductions.hpp"

namespace dgwarp::mpi {

namespace {

// The kinds of error agree passes between processes.
enum ErrorKind : std::int64_t { kind_none = 0, kind_usage = 1, kind_input = 2, kind_invalid = 3, kind_other = 4 };

}  // namespace

void agree(MPI_Comm comm, const std::exception_ptr& error) {
    std::int64_t kind = kind_none, count = 0;
    std::string message;
    if (error) {
        try {
            std::rethrow_exception(error);
        } catch (const UsageError& e) {
            kind = kind_usage;
            message = e.what();
        } catch (const InvalidResultError& e) {
            kind = kind_invalid;
            message = e.what();
            count = e.count();
        } catch (const Error& e) {
            kind = kind_input;
            message = e.what();
        } catch (const std::bad_alloc&) {
            kind = kind_other;
            message = "out of memory";
        } catch (const std::exception& e) {
            kind = kind_other;
            message = e.what();
        } catch (...) {
            kind = kind_other;
            message = "an exception of an unknown type";
        }
    }
    int rank = 0, size = 1;
    MPI_Comm_rank(comm, &rank);
    MPI_Comm_size(comm, &size);
    // The lowest failing rank.
    int failing = kind != kind_none ? rank : size;
    MPI_Allreduce(MPI_IN_PLACE, &failing, 1, MPI_INT, MPI_MIN, comm);
    if (failing == size) return;
    std::int64_t head[2] = {kind, count};
    MPI_Bcast(head, 2, MPI_INT64_T, failing, comm);
    message = broadcast_text(comm, message, failing);
    if (failing == rank) std::rethrow_exception(error);
    message = "process " + std::to_string(failing) + ": " + message;
    switch (head[0]) {
        case kind_usage: throw UsageError(message);
        case kind_invalid: throw InvalidResultError(message, head[1]);
        case kind_input: throw Error(message);
        default: throw std::runtime_error(message);
    }
}

}  // namespace dgwarp::mpi
