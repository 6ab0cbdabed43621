#pragma once
// The coarse level of DG-harmonic (dg_harmonic.hpp): which volume nodes join
// the boundary nodes as vertices of the coarse graph.
#include <array>
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
/// thread count. The volume nodes are visited in their given order when it is
/// spatially coherent (is_coherent_order), else along a Morton curve: `morton`
/// when it is morton_order(dim, points, volume_nodes) already (one entry per
/// volume node), else sorted here. The order changes only the time taken.
std::vector<NodeId> select_coarse_points(int dim, std::span<const double> points,
                                         std::span<const NodeId> boundary_nodes,
                                         std::span<const NodeId> volume_nodes, const CoarseSpacing& spacing,
                                         std::span<const std::uint32_t> morton = {});

// select_coarse_points in three stages, for a mesh whose volume nodes are
// spread over processes (dgwarp/mpi): each process computes its nodes' wants
// and the winners of its cells with the grids of the whole mesh (s_min and
// lo reduced over the processes), and the winners of all processes are
// merged. The result is select_coarse_points' for the whole mesh.

/// Stage 1: the spacing each volume node wants, and the nested grids' base.
struct CoarseWants {
    std::vector<double> want;  // per volume node: its spacing, 0 when it is not a candidate
    double s_min;              // smallest positive want (infinity: no candidate)
    std::array<double, 3> lo;  // lower corner of the volume nodes' bounding box (infinity: no volume node)
};
CoarseWants coarse_wants(int dim, std::span<const double> points, std::span<const NodeId> boundary_nodes,
                         std::span<const NodeId> volume_nodes, const CoarseSpacing& spacing,
                         std::span<const std::uint32_t> morton = {});

/// The best node of one cell of the nested grids.
struct CoarseWinner {
    std::int32_t level;
    std::array<std::int64_t, 3> cell;
    double centre_dist2;  // squared distance to the cell's centre, in cell sizes
    NodeId node;          // ties: the lowest node id wins
};

/// Stage 2: per (level, cell) with grids based on `s_min` and `lo` (of the
/// whole mesh), the candidate nearest to the cell's centre.
std::vector<CoarseWinner> coarse_cell_winners(int dim, std::span<const double> points,
                                              std::span<const NodeId> volume_nodes, std::span<const double> want,
                                              double s_min, const std::array<double, 3>& lo);

/// Stage 3: the winner of each cell among `winners` (several per cell when
/// they come from several processes); their nodes, ascending.
std::vector<NodeId> merge_coarse_winners(std::span<const CoarseWinner> winners);

}  // namespace dgwarp
