#pragma once
// Internal: pieces shared by prepare_dgm and deform_dgm.
#include <cstdint>
#include <span>
#include <vector>

#include "dgwarp/methods/dgm.hpp"

namespace dgwarp::detail {

/// Throws Error when options.max_substeps < 1.
void check_dgm_options(const DgmOptions& options);

/// Barycentric coordinates of every query node in its simplex, threaded.
///  points:       num_points × dim coordinates the graph and the queries are taken from
///  vertex_node:  per graph vertex, the node id giving its position
///  simplices:    num_simplices × (dim + 1) graph vertex ids, non-degenerate
///  query_nodes:  node ids of the queries; query_simplex[i] the simplex of query i
/// Returns query_nodes.size() × (dim + 1) values e_k (corner order of the
/// simplex), summing to 1, with x = sum_k e_k X_k up to round-off; negative
/// for a query outside its simplex.
std::vector<double> barycentric_coordinates(int dim, std::span<const double> points,
                                            std::span<const NodeId> vertex_node,
                                            std::span<const std::int32_t> simplices,
                                            std::span<const NodeId> query_nodes,
                                            std::span<const std::int32_t> query_simplex);

}  // namespace dgwarp::detail
