// part_setup.hpp: markers, tolerance and orientations agreed over the parts.
#include "dgwarp/mpi/part_setup.hpp"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <limits>
#include <unordered_map>

#include "dgwarp/core/error.hpp"
#include "dgwarp/mpi/reductions.hpp"

namespace dgwarp::mpi {

std::vector<std::uint8_t> share_interface_markers(MPI_Comm comm, Mesh& mesh, std::span<const NodeId> interface,
                                                  std::span<const std::int64_t> global_ids) {
    const std::size_t n = mesh.num_points();
    if (global_ids.size() != n)
        throw MeshError("share_interface_markers: " + std::to_string(global_ids.size()) + " global ids for " +
                        std::to_string(n) + " nodes");
    int rank = 0;
    MPI_Comm_rank(comm, &rank);
    std::vector<std::uint8_t> on_interface(n, 0);
    std::unordered_map<std::int64_t, NodeId> local_of;
    local_of.reserve(interface.size());
    std::vector<std::int64_t> ids;
    for (NodeId node : interface) {
        if (node < 0 || static_cast<std::size_t>(node) >= n)
            throw MeshError("share_interface_markers: interface node " + std::to_string(node) + " of a part of " +
                                std::to_string(n) + " nodes",
                            {}, node);
        on_interface[static_cast<std::size_t>(node)] = 1;
        local_of.emplace(global_ids[static_cast<std::size_t>(node)], node);
        ids.push_back(global_ids[static_cast<std::size_t>(node)]);
    }
    // Owners: the lowest rank holding each interface node.
    std::vector<std::int64_t> counts;
    const std::vector<std::int64_t> all_ids = all_gather(comm, ids, &counts);
    std::vector<std::uint8_t> owned(n, 1);
    std::size_t at = 0;
    for (int r = 0; r < static_cast<int>(counts.size()); ++r)
        for (std::int64_t k = 0; k < counts[static_cast<std::size_t>(r)]; ++k, ++at)
            if (r < rank)
                if (const auto it = local_of.find(all_ids[at]); it != local_of.end())
                    owned[static_cast<std::size_t>(it->second)] = 0;
    // (global id, marker) of every interface node on a marker, from every process.
    std::vector<std::vector<NodeId>> nodes_of(mesh.markers.size());
    std::vector<std::int64_t> pairs;
    for (std::size_t m = 0; m < mesh.markers.size(); ++m) {
        nodes_of[m] = marker_nodes(mesh.markers[m]);
        for (NodeId node : nodes_of[m])
            if (on_interface[static_cast<std::size_t>(node)])
                pairs.insert(pairs.end(), {global_ids[static_cast<std::size_t>(node)], static_cast<std::int64_t>(m)});
    }
    const std::vector<std::int64_t> all_pairs = all_gather(comm, pairs);
    std::vector<std::vector<NodeId>> extra(mesh.markers.size());
    for (std::size_t k = 0; k + 1 < all_pairs.size(); k += 2) {
        const auto it = local_of.find(all_pairs[k]);
        const auto m = static_cast<std::size_t>(all_pairs[k + 1]);
        if (it == local_of.end() || m >= mesh.markers.size()) continue;
        if (!std::binary_search(nodes_of[m].begin(), nodes_of[m].end(), it->second)) extra[m].push_back(it->second);
    }
    for (std::size_t m = 0; m < mesh.markers.size(); ++m) {
        std::sort(extra[m].begin(), extra[m].end());
        extra[m].erase(std::unique(extra[m].begin(), extra[m].end()), extra[m].end());
        for (NodeId node : extra[m]) mesh.markers[m].elements.push_back(CellType::vertex, {&node, 1});
    }
    return owned;
}

double bounding_box_diagonal_over_parts(MPI_Comm comm, const Mesh& mesh) {
    double sum = 0;
    const auto dim = static_cast<std::size_t>(mesh.dim);
    for (std::size_t d = 0; d < dim; ++d) {
        double lo = std::numeric_limits<double>::infinity(), hi = -lo;
        for (std::size_t p = d; p < mesh.points.size(); p += dim) {
            lo = std::min(lo, mesh.points[p]);
            hi = std::max(hi, mesh.points[p]);
        }
        lo = min(comm, lo);
        hi = max(comm, hi);
        if (lo <= hi) sum += (hi - lo) * (hi - lo);
    }
    return std::sqrt(sum);
}

std::vector<std::int8_t> dominant_orientations_over_parts(MPI_Comm comm, const Mesh& mesh,
                                                          std::span<const std::int8_t> own) {
    if (own.size() != mesh.cells.size())
        throw MeshError("dominant_orientations_over_parts: " + std::to_string(own.size()) + " orientations for " +
                        std::to_string(mesh.cells.size()) + " cells");
    std::vector<std::int64_t> balance(std::size(all_cell_types), 0);
    for (std::size_t c = 0; c < own.size(); ++c) balance[static_cast<std::size_t>(mesh.cells.types[c])] += own[c];
    balance = sum(comm, std::move(balance));
    std::vector<std::int8_t> orientation(own.size());
    for (std::size_t c = 0; c < orientation.size(); ++c)
        orientation[c] = balance[static_cast<std::size_t>(mesh.cells.types[c])] < 0 ? -1 : 1;
    return orientation;
}

}  // namespace dgwarp::mpi
