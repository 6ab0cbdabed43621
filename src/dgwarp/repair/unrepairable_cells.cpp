#include "dgwarp/repair/unrepairable_cells.hpp"

#include <algorithm>
#include <string>

#include "dgwarp/core/error.hpp"

namespace dgwarp {

std::vector<std::int64_t> cells_with_only_fixed_nodes(const ElementList& cells, std::span<const NodeId> fixed_nodes,
                                                      std::span<const std::int64_t> candidates) {
    std::vector<std::int64_t> out;
    for (const std::int64_t c : candidates) {
        if (c < 0 || static_cast<std::size_t>(c) >= cells.size())
            throw MeshError("cells_with_only_fixed_nodes: cell " + std::to_string(c) + " out of range (" +
                            std::to_string(cells.size()) + " cells)",
                            {}, c);
        const auto nodes = cells.nodes_of(static_cast<std::size_t>(c));
        if (std::all_of(nodes.begin(), nodes.end(),
                        [&](NodeId n) { return std::binary_search(fixed_nodes.begin(), fixed_nodes.end(), n); }))
            out.push_back(c);
    }
    return out;
}

}  // namespace dgwarp
