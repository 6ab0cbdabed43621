#pragma once
// Map from Gmsh node tags (positive, possibly sparse) to 0-based node ids
// (internal to the Gmsh reader).
#include <cstdint>
#include <unordered_map>
#include <vector>

#include "dgwarp/mesh/mesh.hpp"

namespace dgwarp::msh {

/// Tags below `dense_limit` live in a vector indexed by tag (the usual case:
/// tags 1..N), larger ones in a hash map, so memory stays proportional to the
/// number of nodes whatever the tag values. Callers pick dense_limit from the
/// file size so that a file cannot make the vector larger than itself.
class NodeTagMap {
public:
    explicit NodeTagMap(std::int64_t dense_limit) : dense_limit_(dense_limit) {}

    /// Records tag -> id; false (and no change) when the tag is already mapped.
    /// `tag` must be positive.
    bool insert(std::int64_t tag, NodeId id);

    /// The id of `tag`, or -1 when the tag is unknown.
    NodeId find(std::int64_t tag) const {
        if (tag >= 0 && tag < static_cast<std::int64_t>(dense_.size())) return dense_[tag];
        if (sparse_.empty()) return -1;
        const auto it = sparse_.find(tag);
        return it == sparse_.end() ? -1 : it->second;
    }

private:
    std::int64_t dense_limit_;
    std::vector<NodeId> dense_;  // dense_[tag] = id or -1
    std::unordered_map<std::int64_t, NodeId> sparse_;
};

}  // namespace dgwarp::msh
