#pragma once
// Cells that no repair of the volume can change: every node of the cell is
// fixed (on the boundary). When the boundary motion alone inverts such a cell
// (a moving marker sharing nodes with a fixed wall, a face pushed through
// another), no deformation method and no untangling can make the mesh valid;
// saying so at once beats searching for a repair that cannot exist.
#include <cstdint>
#include <span>
#include <vector>

#include "dgwarp/mesh/mesh.hpp"

namespace dgwarp {

/// The cells of `candidates` (indices into `cells`, e.g. the inverted ones)
/// whose every node is in `fixed_nodes` (sorted ascending: BoundarySet::nodes),
/// in the order of `candidates`. Throws MeshError for a candidate out of range.
std::vector<std::int64_t> cells_with_only_fixed_nodes(const ElementList& cells, std::span<const NodeId> fixed_nodes,
                                                      std::span<const std::int64_t> candidates);

}  // namespace dgwarp
