#pragma once
// The coarse level of DG-harmonic (dg_harmonic.hpp): which volume nodes join
// the boundary nodes as vertices of the coarse graph.
#include <cstdint>
#include <span>
#include <vector>

#include "dgwarp/mesh/mesh.hpp"

namespace dgwarp {

struct CoarseSpacing {
    double wall_spacing = 6.0;  // near a wall: this many local boundary spacings
    double growth = 1.0;        // away from the walls: this fraction of the wall distance
};

/// The volume nodes to put on the coarse level, ascending.
///  points:         num_points × dim, row-major
///  boundary_nodes: the boundary node ids
///  volume_nodes:   the candidates (the volume node ids)
/// A volume node x with nearest boundary node j at distance d wants a coarse
/// spacing s(x) = max(wall_spacing h_j, growth d), where h_j is the distance
/// from j to its nearest other boundary point. Nodes closer to a wall than
/// s(x) / 2 are not taken (the boundary node is their coarse point). The
/// others are thinned on nested grids: level l = floor(log2(s / s_min)),
/// cells of size s_min 2^l, and each (level, cell) keeps the node nearest to
/// the cell's centre (lowest id on ties). Deterministic, independent of the
/// thread count.
std::vector<NodeId> select_coarse_points(int dim, std::span<const double> points,
                                         std::span<const NodeId> boundary_nodes,
                                         std::span<const NodeId> volume_nodes, const CoarseSpacing& spacing);

}  // namespace dgwarp
