#include "dgwarp/mpi/distributed_coarse_points.hpp"

#include <algorithm>
#include <unordered_map>

#include "dgwarp/mpi/large_transfers.hpp"

namespace dgwarp::mpi::detail {

namespace {

struct WinnerRecord {
    CoarseWinner winner;  // node: the global id
    double x[3];
};

}  // namespace

CoarsePoints select_coarse_points_distributed(MPI_Comm comm, int dim, std::span<const double> points,
                                              std::span<const NodeId> boundary_nodes,
                                              std::span<const NodeId> volume_nodes,
                                              std::span<const std::int64_t> volume_global_ids,
                                              const CoarseSpacing& spacing) {
    int size = 1;
    MPI_Comm_size(comm, &size);
    CoarseWants w = coarse_wants(dim, points, boundary_nodes, volume_nodes, spacing);
    // The grids of the whole mesh: min is exact, so every process gets the
    // single-process run's s_min and lower corner.
    double local[4] = {w.s_min, w.lo[0], w.lo[1], w.lo[2]}, global[4];
    MPI_Allreduce(local, global, 4, MPI_DOUBLE, MPI_MIN, comm);
    const std::array<double, 3> lo{global[1], global[2], global[3]};
    const std::vector<CoarseWinner> winners = coarse_cell_winners(dim, points, volume_nodes, w.want, global[0], lo);

    // Node ids to global ids: volume_nodes ascend with their global ids, so a
    // process's ties went as they go on one process.
    std::unordered_map<NodeId, std::size_t> position;
    for (std::size_t i = 0; i < volume_nodes.size(); ++i) position.emplace(volume_nodes[i], i);
    std::vector<WinnerRecord> mine(winners.size());
    for (std::size_t k = 0; k < winners.size(); ++k) {
        mine[k].winner = winners[k];
        mine[k].winner.node = volume_global_ids[position.at(winners[k].node)];
        for (int d = 0; d < 3; ++d)
            mine[k].x[d] = d < dim ? points[static_cast<std::size_t>(winners[k].node) * dim + d] : 0.0;
    }
    const std::vector<WinnerRecord> all = allgather_records<WinnerRecord>(comm, mine);

    std::vector<CoarseWinner> candidates(all.size());
    std::unordered_map<std::int64_t, const double*> where;
    for (std::size_t k = 0; k < all.size(); ++k) {
        candidates[k] = all[k].winner;
        where.emplace(all[k].winner.node, all[k].x);
    }
    CoarsePoints c;
    const std::vector<NodeId> chosen = merge_coarse_winners(candidates);
    c.global_ids.assign(chosen.begin(), chosen.end());
    for (std::int64_t id : c.global_ids)
        for (int d = 0; d < dim; ++d) c.points.push_back(where.at(id)[d]);
    return c;
}

}  // namespace dgwarp::mpi::detail
