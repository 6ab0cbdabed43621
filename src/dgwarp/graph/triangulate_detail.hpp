#pragma once
// Internal: the CGAL stages of build_located_graph, one function per
// dimension (triangulate_2d.cpp, triangulate_3d.cpp), both the one template
// of triangulate_cgal.hpp. Not part of the API.
#include <cstdint>
#include <functional>
#include <span>
#include <vector>

#include "dgwarp/core/progress.hpp"
#include "dgwarp/graph/delaunay_graph.hpp"

namespace dgwarp::detail {

using VisitOrderFn = std::function<std::span<const std::uint32_t>()>;
/// Work on the triangulation's simplices run beside the location (may be empty).
using BesideLocateFn = std::function<void(std::vector<std::int32_t>& simplices)>;

struct TriangulationResult {
    std::vector<std::int32_t> simplices;  // num_simplices × (dim+1) graph vertex ids
    GraphLocation location;
    GraphTimings timings;
};

/// Delaunay triangulation of the points `vertex_node[v]` (graph vertex v; all
/// distinct), then location of `query_nodes`. `points` is num_points × dim.
/// `visit_order` gives the order in which to locate query_nodes (indices into
/// it, a permutation; empty: as given); it is called beside the
/// triangulation's build (run_concurrently), and the span it returns must
/// stay valid until this returns. `locate_progress` gets the fraction of the
/// queries located, per block. `beside_locate`, when set, is called with
/// the simplices (which it may read, or swap away and back) on this thread
/// while the location runs beside it on a thread of its own (run_beside).
/// Throws MeshError when the vertices do not span the plane / space.
TriangulationResult triangulate_and_locate_2d(std::span<const double> points,
                                              std::span<const NodeId> vertex_node,
                                              std::span<const NodeId> query_nodes,
                                              const VisitOrderFn& visit_order,
                                              const ProgressFn& locate_progress,
                                              const BesideLocateFn& beside_locate = {});
TriangulationResult triangulate_and_locate_3d(std::span<const double> points,
                                              std::span<const NodeId> vertex_node,
                                              std::span<const NodeId> query_nodes,
                                              const VisitOrderFn& visit_order,
                                              const ProgressFn& locate_progress,
                                              const BesideLocateFn& beside_locate = {});

/// Queries are located in blocks of this many visits, each block walking from
/// its own start, so blocks can run in parallel and the result does not
/// depend on the thread count.
inline constexpr std::int64_t locate_block_size = 8192;

}  // namespace dgwarp::detail
