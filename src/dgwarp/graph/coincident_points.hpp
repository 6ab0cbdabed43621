#pragma once
// Grouping of boundary points with identical coordinates into one graph vertex.
#include <cstdint>
#include <span>
#include <vector>

#include "dgwarp/mesh/mesh.hpp"

namespace dgwarp {

/// Groups of exactly equal points, as compressed rows.
struct CoincidentGroups {
    /// Group g holds list positions members[offsets[g] .. offsets[g+1]),
    /// ascending; groups are ordered by their first member.
    std::vector<std::int32_t> offsets{0};
    std::vector<std::int32_t> members;

    std::size_t size() const { return offsets.size() - 1; }
};

/// Groups the points `nodes[k]` (k = 0 .. nodes.size()-1) of `points`
/// (num_points × dim, row-major) whose coordinates are bitwise equal (+0 and
/// -0 count as equal). Every k is in exactly one group.
CoincidentGroups group_coincident_points(int dim, std::span<const double> points,
                                         std::span<const NodeId> nodes);

}  // namespace dgwarp
