#include "dgwarp/mpi/large_transfers.hpp"

#include <algorithm>
#include <climits>
#include <string>

#include "dgwarp/core/error.hpp"

namespace dgwarp::mpi::detail {

RecordType::RecordType(std::size_t bytes) {
    if (bytes == 0 || bytes > static_cast<std::size_t>(INT_MAX)) throw Error("an MPI record of " + std::to_string(bytes) + " bytes");
    MPI_Type_contiguous(static_cast<int>(bytes), MPI_BYTE, &type_);
    MPI_Type_commit(&type_);
}

RecordType::~RecordType() {
    if (type_ != MPI_DATATYPE_NULL) MPI_Type_free(&type_);
}

std::int64_t default_chunk_records(int size) { return std::max<std::int64_t>(1, INT_MAX / std::max(size, 1)); }

std::vector<std::byte> allgather_bytes(MPI_Comm comm, std::span<const std::byte> mine, std::size_t record,
                                       std::int64_t chunk_records) {
    int rank = 0, size = 1;
    MPI_Comm_rank(comm, &rank);
    MPI_Comm_size(comm, &size);
    const RecordType type(record);
    const auto my_count = static_cast<std::int64_t>(mine.size() / record);
    std::vector<std::int64_t> counts(static_cast<std::size_t>(size));
    MPI_Allgather(&my_count, 1, MPI_INT64_T, counts.data(), 1, MPI_INT64_T, comm);
    const std::int64_t chunk =
        std::min(chunk_records > 0 ? chunk_records : default_chunk_records(size), default_chunk_records(size));
    std::vector<std::int64_t> offset(static_cast<std::size_t>(size) + 1, 0);
    for (int r = 0; r < size; ++r) offset[static_cast<std::size_t>(r) + 1] = offset[static_cast<std::size_t>(r)] + counts[static_cast<std::size_t>(r)];
    std::vector<std::byte> all(static_cast<std::size_t>(offset.back()) * record);
    const std::int64_t largest = *std::max_element(counts.begin(), counts.end());
    if (largest == 0) return all;
    // One round when everything fits (every process's records at once, as MPI_Allgatherv).
    std::vector<int> n(static_cast<std::size_t>(size)), displs(static_cast<std::size_t>(size));
    std::vector<std::byte> round;
    for (std::int64_t start = 0; start < largest; start += chunk) {
        int total = 0;
        for (int r = 0; r < size; ++r) {
            const auto k = static_cast<std::size_t>(r);
            n[k] = static_cast<int>(std::clamp<std::int64_t>(counts[k] - start, 0, chunk));
            displs[k] = total;
            total += n[k];
        }
        const bool direct = start == 0 && chunk >= largest;  // no copy: straight into place
        if (!direct) round.resize(static_cast<std::size_t>(total) * record);
        MPI_Allgatherv(mine.data() + static_cast<std::size_t>(start) * record, n[static_cast<std::size_t>(rank)], type.get(),
                       direct ? all.data() : round.data(), n.data(), displs.data(), type.get(), comm);
        if (direct) break;
        for (int r = 0; r < size; ++r) {
            const auto k = static_cast<std::size_t>(r);
            std::copy_n(round.data() + static_cast<std::size_t>(displs[k]) * record, static_cast<std::size_t>(n[k]) * record,
                        all.data() + static_cast<std::size_t>(offset[k] + start) * record);
        }
    }
    return all;
}

void send_bytes(MPI_Comm comm, std::span<const std::byte> bytes, int to, int tag, std::int64_t piece) {
    const auto n = static_cast<long long>(bytes.size());
    MPI_Send(&n, 1, MPI_LONG_LONG, to, tag, comm);
    const std::int64_t step = piece > 0 ? std::min<std::int64_t>(piece, INT_MAX) : INT_MAX;
    for (std::int64_t at = 0; at < n; at += step)
        MPI_Send(bytes.data() + at, static_cast<int>(std::min<std::int64_t>(step, n - at)), MPI_BYTE, to, tag, comm);
}

std::vector<std::byte> receive_bytes(MPI_Comm comm, int from, int tag, std::int64_t piece) {
    long long n = 0;
    MPI_Recv(&n, 1, MPI_LONG_LONG, from, tag, comm, MPI_STATUS_IGNORE);
    std::vector<std::byte> bytes(static_cast<std::size_t>(n));
    const std::int64_t step = piece > 0 ? std::min<std::int64_t>(piece, INT_MAX) : INT_MAX;
    for (std::int64_t at = 0; at < n; at += step)
        MPI_Recv(bytes.data() + at, static_cast<int>(std::min<std::int64_t>(step, n - at)), MPI_BYTE, from, tag, comm,
                 MPI_STATUS_IGNORE);
    return bytes;
}

}  // namespace dgwarp::mpi::detail
