#pragma once
// A cheap spatial order of mesh nodes: along a Morton (Z-order) curve. Loops
// that query a spatial structure (a k-d tree, a triangulation) node by node
// run several times faster in this order than in a spatially random one,
// such as the node numbering of Gmsh's 3D Delaunay.
#include <cstdint>
#include <span>
#include <vector>

#include "dgwarp/mesh/mesh.hpp"

namespace dgwarp {

/// The positions 0..nodes.size()-1 of `nodes` (ids into `points`,
/// num_points × dim) sorted along a Morton curve over their bounding box
/// (21 bits per axis); ties keep the given order. Deterministic.
std::vector<std::uint32_t> morton_order(int dim, std::span<const double> points, std::span<const NodeId> nodes);

}  // namespace dgwarp
