// reductions.hpp over MPI's collectives, large sizes in pieces.
#include "dgwarp/mpi/reductions.hpp"

#include <algorithm>
#include <climits>
#include <span>

#include "dgwarp/mpi/large_transfers.hpp"

namespace dgwarp::mpi {

int rank_in(MPI_Comm comm) {
    int rank = 0;
    MPI_Comm_rank(comm, &rank);
    return rank;
}

int processes_in(MPI_Comm comm) {
    int size = 1;
    MPI_Comm_size(comm, &size);
    return size;
}

namespace {

template <class T>
T reduced(MPI_Comm comm, T value, MPI_Datatype type, MPI_Op op) {
    MPI_Allreduce(MPI_IN_PLACE, &value, 1, type, op, comm);
    return value;
}

template <class T>
std::vector<T> reduced(MPI_Comm comm, std::vector<T> values, MPI_Datatype type, MPI_Op op) {
    for (std::size_t at = 0; at < values.size(); at += INT_MAX) {
        const int n = static_cast<int>(std::min<std::size_t>(INT_MAX, values.size() - at));
        MPI_Allreduce(MPI_IN_PLACE, values.data() + at, n, type, op, comm);
    }
    return values;
}

}  // namespace

std::int64_t sum(MPI_Comm comm, std::int64_t value) { return reduced(comm, value, MPI_INT64_T, MPI_SUM); }
std::vector<std::int64_t> sum(MPI_Comm comm, std::vector<std::int64_t> values) {
    return reduced(comm, std::move(values), MPI_INT64_T, MPI_SUM);
}
std::vector<double> sum(MPI_Comm comm, std::vector<double> values) {
    return reduced(comm, std::move(values), MPI_DOUBLE, MPI_SUM);
}
double min(MPI_Comm comm, double value) { return reduced(comm, value, MPI_DOUBLE, MPI_MIN); }
double max(MPI_Comm comm, double value) { return reduced(comm, value, MPI_DOUBLE, MPI_MAX); }
std::int64_t min(MPI_Comm comm, std::int64_t value) { return reduced(comm, value, MPI_INT64_T, MPI_MIN); }
std::int64_t max(MPI_Comm comm, std::int64_t value) { return reduced(comm, value, MPI_INT64_T, MPI_MAX); }

std::vector<std::int64_t> all_gather(MPI_Comm comm, const std::vector<std::int64_t>& values,
                                     std::vector<std::int64_t>* counts) {
    if (counts) {
        const auto mine = static_cast<std::int64_t>(values.size());
        *counts = detail::allgather_records(comm, std::span<const std::int64_t>(&mine, 1));
    }
    return detail::allgather_records(comm, std::span<const std::int64_t>(values));
}

std::vector<std::string> gather_text(MPI_Comm comm, const std::string& text, int root) {
    int rank = 0, size = 1;
    MPI_Comm_rank(comm, &rank);
    MPI_Comm_size(comm, &size);
    constexpr int tag = 7301;
    if (rank != root) {
        detail::send_bytes(comm, std::as_bytes(std::span<const char>(text)), root, tag);
        return {};
    }
    std::vector<std::string> texts(static_cast<std::size_t>(size));
    for (int r = 0; r < size; ++r) {
        if (r == root) {
            texts[static_cast<std::size_t>(r)] = text;
            continue;
        }
        const std::vector<std::byte> bytes = detail::receive_bytes(comm, r, tag);
        texts[static_cast<std::size_t>(r)].assign(reinterpret_cast<const char*>(bytes.data()), bytes.size());
    }
    return texts;
}

std::string broadcast_text(MPI_Comm comm, const std::string& text, int root) {
    int rank = 0;
    MPI_Comm_rank(comm, &rank);
    long long n = static_cast<long long>(text.size());
    MPI_Bcast(&n, 1, MPI_LONG_LONG, root, comm);
    std::string out = rank == root ? text : std::string(static_cast<std::size_t>(n), '\0');
    for (std::size_t at = 0; at < out.size(); at += INT_MAX) {
        const int piece = static_cast<int>(std::min<std::size_t>(INT_MAX, out.size() - at));
        MPI_Bcast(out.data() + at, piece, MPI_CHAR, root, comm);
    }
    return out;
}

}  // namespace dgwarp::mpi
