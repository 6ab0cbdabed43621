#include "dgwarp/io/gmsh/gmsh_node_tags.hpp"

#include <algorithm>

namespace dgwarp::msh {

bool NodeTagMap::insert(std::int64_t tag, NodeId id) {
    if (tag < dense_limit_) {
        if (tag >= static_cast<std::int64_t>(dense_.size())) {
            // Grow geometrically (amortised O(1)), but never past the limit.
            const std::int64_t size = std::min(dense_limit_, std::max<std::int64_t>(tag + 1, 2 * static_cast<std::int64_t>(dense_.size())));
            dense_.resize(static_cast<std::size_t>(size), -1);
        }
        if (dense_[tag] != -1) return false;
        dense_[tag] = id;
        return true;
    }
    return sparse_.emplace(tag, id).second;
}

}  // namespace dgwarp::msh
