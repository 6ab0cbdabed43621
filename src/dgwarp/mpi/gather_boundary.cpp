#include "dgwarp/mpi/gather_boundary.hpp"

#include <algorithm>
#include <numeric>
#include <string>

#include "dgwarp/core/error.hpp"
#include "dgwarp/mpi/collective_checks.hpp"
#include "dgwarp/mpi/large_transfers.hpp"

namespace dgwarp::mpi::detail {

namespace {

struct Record {
    std::int64_t global_id;
    std::int32_t rank;
    std::int32_t moving;
    double x[3];
};

}  // namespace

GatheredBoundary gather_boundary(MPI_Comm comm, int dim, std::span<const double> points,
                                 std::span<const std::int64_t> global_ids, const BoundarySet& boundary) {
    int rank = 0, size = 1;
    MPI_Comm_rank(comm, &rank);
    MPI_Comm_size(comm, &size);
    std::vector<Record> mine(boundary.nodes.size());
    for (std::size_t j = 0; j < mine.size(); ++j) {
        const auto n = static_cast<std::size_t>(boundary.nodes[j]);
        mine[j] = {global_ids[n], rank, boundary.moving[j], {0, 0, 0}};
        for (int d = 0; d < dim; ++d) mine[j].x[d] = points[n * dim + d];
    }
    // Counted in records, in rounds when they exceed MPI's int counts (large_transfers.hpp).
    std::vector<Record> all = allgather_records<Record>(comm, mine);

    // Sorted by global id, then rank: the first record of an id is its owner's.
    std::sort(all.begin(), all.end(), [](const Record& a, const Record& b) {
        return a.global_id != b.global_id ? a.global_id < b.global_id : a.rank < b.rank;
    });
    GatheredBoundary g;
    std::string error;
    for (std::size_t i = 0; i < all.size(); ++i) {
        const Record& r = all[i];
        if (i > 0 && all[i - 1].global_id == r.global_id) {
            const Record& first = all[i - 1];
            bool same = first.moving == r.moving;
            for (int d = 0; d < dim; ++d) same = same && first.x[d] == r.x[d];
            if (!same && error.empty())
                error = "boundary node " + std::to_string(r.global_id) + " differs between processes " +
                        std::to_string(first.rank) + " and " + std::to_string(r.rank) +
                        " (coordinates or moving flag)";
            continue;
        }
        g.global_ids.push_back(r.global_id);
        g.moving.push_back(static_cast<std::uint8_t>(r.moving));
        g.owner.push_back(r.rank);
        for (int d = 0; d < dim; ++d) g.points.push_back(r.x[d]);
    }
    // Every process found the same error in the same records: all throw it.
    if (!error.empty()) throw MeshError(error, {}, -1);
    g.local_index.resize(mine.size());
    for (std::size_t j = 0; j < mine.size(); ++j)
        g.local_index[j] = static_cast<std::int32_t>(
            std::lower_bound(g.global_ids.begin(), g.global_ids.end(), mine[j].global_id) - g.global_ids.begin());
    return g;
}

}  // namespace dgwarp::mpi::detail
