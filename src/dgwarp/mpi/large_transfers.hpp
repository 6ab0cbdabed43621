#pragma once
// Internal: MPI transfers whose sizes do not fit MPI's int counts. Counts go
// in records (a contiguous datatype of the record's size), not bytes, and a
// gather larger than an int of records over all processes goes in rounds of
// at most `chunk` records per process. Point-to-point vectors go in pieces.
#include <mpi.h>

#include <climits>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <span>
#include <type_traits>
#include <vector>

namespace dgwarp::mpi::detail {

/// The largest number of records a process sends per round by default: what
/// keeps every round's total (over `size` processes) within an int.
std::int64_t default_chunk_records(int size);

/// Collective: every process's `mine` (records of `record` bytes each),
/// concatenated in rank order, on every process. Rounds of at most
/// `chunk_records` records per process (default_chunk_records when <= 0).
std::vector<std::byte> allgather_bytes(MPI_Comm comm, std::span<const std::byte> mine, std::size_t record,
                                       std::int64_t chunk_records = 0);

/// allgather_bytes of trivially copyable records.
template <class T>
std::vector<T> allgather_records(MPI_Comm comm, std::span<const T> mine, std::int64_t chunk_records = 0) {
    static_assert(std::is_trivially_copyable_v<T>);
    const std::vector<std::byte> bytes = allgather_bytes(comm, std::as_bytes(mine), sizeof(T), chunk_records);
    std::vector<T> out(bytes.size() / sizeof(T));
    if (!bytes.empty()) std::memcpy(out.data(), bytes.data(), bytes.size());
    return out;
}

/// Point to point: `bytes` to `to` (its size first, then pieces of at most
/// `piece` bytes, INT_MAX when <= 0); receive_bytes gets them from `from`.
void send_bytes(MPI_Comm comm, std::span<const std::byte> bytes, int to, int tag, std::int64_t piece = 0);
std::vector<std::byte> receive_bytes(MPI_Comm comm, int from, int tag, std::int64_t piece = 0);

/// A committed contiguous datatype of `bytes` bytes (freed by the destructor):
/// counts in records, not bytes.
class RecordType {
public:
    explicit RecordType(std::size_t bytes);
    ~RecordType();
    RecordType(const RecordType&) = delete;
    RecordType& operator=(const RecordType&) = delete;
    MPI_Datatype get() const { return type_; }

private:
    MPI_Datatype type_ = MPI_DATATYPE_NULL;
};

}  // namespace dgwarp::mpi::detail
