#pragma once
// Checks and measures shared by the methods' prepare functions: the boundary
// set against the point array, and the size of the boundary.
#include <cstddef>
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

}  // namespace dgwarp
