#pragma once
// Checks every method's prepare makes on its inputs (points and boundary set).
#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "dgwarp/motion/node_motion.hpp"

namespace dgwarp {

/// Checks that dim is 2 or 3, that `points` is a whole number of dim-D points
/// that int32 node ids can address, and that `boundary` is consistent with
/// them (as many moving flags as nodes, flags 0 or 1, node ids sorted, unique
/// and in range). Returns the number of points. `method` names the method in
/// messages ("DG-IDW", "DGM"). Throws MeshError (with the node id when one node
/// is at fault).
std::size_t check_points_and_boundary(std::string_view method, int dim, std::span<const double> points,
                                      const BoundarySet& boundary);

/// The volume nodes (every node id in [0, num_points) not in boundary.nodes,
/// ascending), and node_simplex sized num_points with -1 - b for the boundary
/// node of boundary index b (volume entries left 0 for the caller to fill).
/// boundary.nodes must be sorted (check_points_and_boundary).
std::vector<NodeId> split_volume_nodes(std::size_t num_points, const BoundarySet& boundary,
                                       std::vector<std::int32_t>& node_simplex);

/// Bytes held by a vector's elements (for the plans' memory figures).
template <class T>
std::size_t bytes_of(const std::vector<T>& v) {
    return v.size() * sizeof(T);
}

/// Checks one step's arrays against a plan of `num_points` points of `dim`
/// coordinates and `boundary_nodes`: points and out hold num_points × dim
/// values, motion one entry per boundary node, every motion usable
/// (motion_value_problem: finite, at most max_motion_value). Throws MeshError
/// naming `method` (and the boundary node of an unusable motion).
void check_step_arrays(std::string_view method, std::int64_t num_points, int dim,
                       std::span<const NodeId> boundary_nodes, std::span<const double> points,
                       const BoundaryMotion& motion, std::span<const double> out);

/// What is wrong with one step's result `out` (num_points × dim, row-major):
/// empty when every coordinate is finite; otherwise a message naming the
/// first node with a non-finite coordinate, its coordinates, how many nodes
/// have one (`count`), and the cause: the motion's largest translation,
/// rotation and centre, beyond what double arithmetic holds, or else the
/// method's weights overflowing. `method` names the method ("dg-idw").
std::string non_finite_result(std::string_view method, int dim, std::span<const double> out,
                              const BoundaryMotion& motion, std::int64_t& count);

/// Throws InvalidResultError (count: the nodes) with non_finite_result's
/// message when a coordinate of `out` is not finite: no method returns one.
void check_step_result(std::string_view method, int dim, std::span<const double> out, const BoundaryMotion& motion);

}  // namespace dgwarp
