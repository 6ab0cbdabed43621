// prepare_dgm: the Delaunay graph, point location and barycentric coordinates.
#include <algorithm>
#include <string>

#include "dgwarp/core/error.hpp"
#include "dgwarp/core/parallel_for.hpp"
#include "dgwarp/core/stopwatch.hpp"
#include "dgwarp/graph/barycentric.hpp"
#include "dgwarp/methods/boundary_graph.hpp"
#include "dgwarp/methods/dgm.hpp"
#include "dgwarp/methods/dgm_detail.hpp"
#include "dgwarp/methods/method_inputs.hpp"

namespace dgwarp {

namespace detail {

void check_dgm_options(const DgmOptions& options) {
    if (options.max_substeps < 1)
        throw Error("DGM: max_substeps must be at least 1, got " + std::to_string(options.max_substeps));
}

std::vector<double> barycentric_coordinates(int dim, std::span<const double> points,
                                            std::span<const NodeId> vertex_node,
                                            std::span<const std::int32_t> simplices,
                                            std::span<const NodeId> query_nodes,
                                            std::span<const std::int32_t> query_simplex) {
    const int corners = dim + 1;
    std::vector<double> e(query_nodes.size() * static_cast<std::size_t>(corners));
    // The vertices' points in one small array (it stays in cache), and each
    // node's simplex row asked for ahead: in a spatially random numbering the
    // rows are far apart (as in DG-IDW's weights, dg_idw_prepare.cpp).
    const std::vector<double> vertex_points = gather_points(dim, points, vertex_node);
    constexpr std::int64_t row_ahead = 16;
    const auto n = static_cast<std::int64_t>(query_nodes.size());
    parallel_for(n, [&](std::int64_t i) {
        if (i + row_ahead < n)
            __builtin_prefetch(simplices.data() + static_cast<std::size_t>(query_simplex[i + row_ahead]) * corners);
        const std::int32_t* c = simplices.data() + static_cast<std::size_t>(query_simplex[i]) * corners;
        const double* p[4];
        for (int k = 0; k < corners; ++k) p[k] = vertex_points.data() + static_cast<std::size_t>(c[k]) * dim;
        const double* x = points.data() + static_cast<std::size_t>(query_nodes[i]) * dim;
        double* out = e.data() + static_cast<std::size_t>(i) * corners;
        barycentric(dim, x, p, out);
    });
    return e;
}

}  // namespace detail

DgmPlan prepare_dgm(int dim, std::span<const double> points, const BoundarySet& boundary,
                    const DgmOptions& options, const ProgressFn& progress) {
    const std::size_t num_points = check_points_and_boundary("DGM", dim, points, boundary);
    detail::check_dgm_options(options);

    DgmPlan plan;
    plan.dim = dim;
    plan.boundary_nodes = boundary.nodes;
    plan.boundary_moving = boundary.moving;
    BoundaryGraph bg =
        prepare_boundary_graph(plan, dim, points, boundary, num_points, progress_part(progress, 0, 0.9));
    const std::vector<NodeId>& volume = bg.volume;
    LocatedGraph& lg = bg.located;
    plan.vertex_motion = std::move(bg.vertex_motion.vertex_motion);

    const auto t0 = Clock::now();
    const DelaunayGraph& g = lg.graph;

    std::vector<NodeId> vertex_node(g.num_vertices());
    for (std::size_t v = 0; v < vertex_node.size(); ++v) vertex_node[v] = boundary.nodes[g.vertex_nodes[g.vertex_offsets[v]]];
    plan.node_barycentric =
        detail::barycentric_coordinates(dim, points, vertex_node, g.simplices, volume, lg.location.simplex);
    for (std::size_t i = 0; i < volume.size(); ++i) plan.node_simplex[volume[i]] = lg.location.simplex[i];
    plan.simplices = std::move(lg.graph.simplices);
    plan.stats.barycentric_seconds = seconds_since(t0);
    if (progress) progress(1.0);
    return plan;
}

std::size_t plan_bytes(const DgmPlan& plan) {
    return sizeof(DgmPlan) + core_bytes(plan) + bytes_of(plan.simplices) + bytes_of(plan.vertex_motion) +
           bytes_of(plan.node_barycentric);
}

}  // namespace dgwarp
