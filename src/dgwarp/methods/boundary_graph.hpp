#pragma once
// The graph stage of DG-IDW's and DGM's prepare (METHODS.md, DG-IDW prepare
// steps 1 and 2): the Delaunay graph of the boundary nodes, every volume node
// located in it, and how each graph vertex moves. Internal to the methods.
#include <cstdint>
#include <functional>
#include <span>
#include <utility>
#include <vector>

#include "dgwarp/core/progress.hpp"
#include "dgwarp/graph/delaunay_graph.hpp"
#include "dgwarp/methods/graph_vertex_motion.hpp"

namespace dgwarp {

struct BoundaryGraph {
    std::vector<NodeId> volume;       // every node not in boundary.nodes, ascending
    LocatedGraph located;             // the graph, the simplex of each node of `volume`, the timings
    GraphVertexMotion vertex_motion;  // per graph vertex (graph_vertex_motion.hpp)
};

/// The graph stage for `num_points` points (num_points × dim, checked by
/// check_points_and_boundary) and `boundary`. node_simplex is sized num_points
/// with -1 - b for the boundary node of boundary index b (split_volume_nodes;
/// the volume nodes' entries are left for the caller). `progress` goes to 1
/// while the volume nodes are located.
/// `beside_build` goes to GraphOptions::beside_build.
BoundaryGraph build_boundary_graph(int dim, std::span<const double> points, const BoundarySet& boundary,
                                   std::size_t num_points, std::vector<std::int32_t>& node_simplex,
                                   const ProgressFn& progress, const std::function<void()>& beside_build = {});

/// The graph stage for `plan` (a DgIdwPlan or DgmPlan): fills its
/// node_simplex (boundary entries), shared_offsets, shared_members and the
/// stage's stats (graph and locate seconds, outside_count,
/// shared_vertex_count), and returns the rest (the shared groups moved out).
template <class Plan>
BoundaryGraph prepare_boundary_graph(Plan& plan, int dim, std::span<const double> points, const BoundarySet& boundary,
                                     std::size_t num_points, const ProgressFn& progress,
                                     const std::function<void()>& beside_build = {}) {
    BoundaryGraph g = build_boundary_graph(dim, points, boundary, num_points, plan.node_simplex, progress, beside_build);
    plan.stats.graph_seconds = g.located.timings.triangulate_seconds;
    plan.stats.locate_seconds = g.located.timings.locate_seconds;
    plan.stats.outside_count = g.located.location.outside_count;
    plan.stats.shared_vertex_count = static_cast<std::int64_t>(g.vertex_motion.shared_offsets.size()) - 1;
    plan.shared_offsets = std::move(g.vertex_motion.shared_offsets);
    plan.shared_members = std::move(g.vertex_motion.shared_members);
    return g;
}

}  // namespace dgwarp
