#pragma once
// Helpers on a BoundarySet shared by the methods: checks against the point
// array, the size of the boundary, and walking the volume nodes (the nodes
// not in the boundary set) in id order.
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <span>
#include <string_view>

#include "dgwarp/motion/node_motion.hpp"

namespace dgwarp {

/// The number of points in `points` (num_points × dim, row-major). Throws
/// MeshError naming `method` when dim is not 2 or 3, the array is not a whole
/// number of points, or there are more points than int32 node ids can hold.
std::size_t checked_point_count(std::string_view method, int dim, std::span<const double> points);

/// Throws MeshError when `boundary` does not fit a mesh of `num_points`
/// points: flags and nodes of different sizes, ids out of range, unsorted or
/// repeated ids, a moving flag other than 0 or 1. The error carries the node id.
void check_boundary_set(std::size_t num_points, const BoundarySet& boundary);

/// Diagonal of the bounding box of the boundary nodes (all of them when
/// `moving_only` is false, else those flagged moving) in `points`
/// (num_points × dim); 0 when there are none.
double boundary_diagonal(int dim, std::span<const double> points, const BoundarySet& boundary, bool moving_only);

/// The id of volume node v: the v-th node (0-based, in id order) whose id is
/// not in `boundary` (sorted, unique ids). O(log num_boundary).
NodeId volume_node_id(std::span<const NodeId> boundary, std::int64_t v);

/// Walks the volume nodes in id order, starting at volume node v: next()
/// returns v's id, then the following volume node's, and so on.
class VolumeNodeCursor {
public:
    VolumeNodeCursor(std::span<const NodeId> boundary, std::int64_t v)
        : boundary_(boundary), node_(volume_node_id(boundary, v)),
          next_boundary_(std::lower_bound(boundary.begin(), boundary.end(), node_) - boundary.begin()) {}

    NodeId next() {
        while (next_boundary_ < boundary_.size() && boundary_[next_boundary_] == node_) {
            ++next_boundary_;
            ++node_;
        }
        return node_++;
    }

private:
    std::span<const NodeId> boundary_;
    NodeId node_;
    std::size_t next_boundary_;
};

}  // namespace dgwarp
