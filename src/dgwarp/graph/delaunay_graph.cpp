#include "dgwarp/graph/delaunay_graph.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "dgwarp/core/error.hpp"
#include "dgwarp/core/stopwatch.hpp"
#include "dgwarp/graph/coincident_points.hpp"
#include "dgwarp/graph/morton_order.hpp"
#include "dgwarp/graph/triangulate_detail.hpp"

namespace dgwarp {

namespace {

void check_nodes(int dim, std::span<const double> points, std::span<const NodeId> nodes,
                 const char* what) {
    const auto num_points = static_cast<std::int64_t>(points.size() / static_cast<std::size_t>(dim));
    for (std::size_t k = 0; k < nodes.size(); ++k) {
        const NodeId n = nodes[k];
        if (n < 0 || n >= num_points)
            throw MeshError(std::string(what) + " node id " + std::to_string(n) + " is out of range (the mesh has " +
                                std::to_string(num_points) + " points)",
                            {}, n);
        for (int d = 0; d < dim; ++d)
            if (!std::isfinite(points[static_cast<std::size_t>(n) * dim + d]))
                throw MeshError(std::string(what) + " node " + std::to_string(n) + " has a non-finite coordinate",
                                {}, n);
    }
}

}  // namespace

bool is_coherent_order(int dim, std::span<const double> points, std::span<const NodeId> nodes) {
    if (nodes.size() < 2) return true;
    double lo[3], hi[3];
    for (int d = 0; d < dim; ++d) lo[d] = hi[d] = points[static_cast<std::size_t>(nodes[0]) * dim + d];
    double path = 0;
    for (std::size_t i = 1; i < nodes.size(); ++i) {
        const double* a = points.data() + static_cast<std::size_t>(nodes[i - 1]) * dim;
        const double* b = points.data() + static_cast<std::size_t>(nodes[i]) * dim;
        double sq = 0;
        for (int d = 0; d < dim; ++d) {
            sq += (b[d] - a[d]) * (b[d] - a[d]);
            lo[d] = std::min(lo[d], b[d]);
            hi[d] = std::max(hi[d], b[d]);
        }
        path += std::sqrt(sq);
    }
    double volume = 1;
    for (int d = 0; d < dim; ++d) volume *= hi[d] - lo[d];
    const double spacing = std::pow(volume / static_cast<double>(nodes.size()), 1.0 / dim);
    return path / static_cast<double>(nodes.size() - 1) <= 4 * spacing;
}

LocatedGraph build_located_graph(int dim, std::span<const double> points,
                                 std::span<const NodeId> boundary_nodes,
                                 std::span<const NodeId> query_nodes, const GraphOptions& options,
                                 const ProgressFn& progress) {
    if (dim != 2 && dim != 3) throw MeshError("the Delaunay graph needs dim 2 or 3, got " + std::to_string(dim));
    if (points.size() % static_cast<std::size_t>(dim) != 0)
        throw MeshError("the point array holds " + std::to_string(points.size()) +
                        " values, not a whole number of " + std::to_string(dim) + "D points");
    check_nodes(dim, points, boundary_nodes, "boundary");

    const auto t0 = Clock::now();
    LocatedGraph out;
    out.graph.dim = dim;
    CoincidentGroups groups = group_coincident_points(dim, points, boundary_nodes);
    if (groups.size() < static_cast<std::size_t>(dim + 1))
        throw MeshError("the Delaunay graph needs at least " + std::to_string(dim + 1) +
                        " distinct boundary points in " + std::to_string(dim) + "D, got " +
                        std::to_string(groups.size()) + " (from " + std::to_string(boundary_nodes.size()) +
                        " boundary nodes)");
    std::vector<NodeId> vertex_node(groups.size());
    for (std::size_t v = 0; v < groups.size(); ++v) vertex_node[v] = boundary_nodes[groups.members[groups.offsets[v]]];
    out.graph.vertex_offsets = std::move(groups.offsets);
    out.graph.vertex_nodes = std::move(groups.members);
    const double group_seconds = seconds_since(t0);

    // The visiting order (and the caller's side work), beside the triangulation's build.
    bool spatial = false;
    std::vector<std::uint32_t> morton;
    const detail::VisitOrderFn visit_order = [&]() -> std::span<const std::uint32_t> {
        check_nodes(dim, points, query_nodes, "query");  // here: the build needs only the boundary nodes
        if (options.beside_build) options.beside_build();
        spatial = options.order == LocateOrder::morton ||
                  (options.order == LocateOrder::automatic && !is_coherent_order(dim, points, query_nodes));
        if (!spatial) return {};  // as given
        if (options.morton.size() == query_nodes.size()) return options.morton;
        morton = morton_order(dim, points, query_nodes);
        return morton;
    };
    if (progress) progress(0.0);
    const ProgressFn locate_progress = progress_part(progress, graph_progress_share, 1.0);
    detail::BesideLocateFn beside_locate;
    if (options.beside_locate)
        beside_locate = [&](std::vector<std::int32_t>& simplices) {
            out.graph.simplices.swap(simplices);  // the graph whole for the call, the simplices back after it
            try {
                options.beside_locate(out.graph);
            } catch (...) {
                out.graph.simplices.swap(simplices);
                throw;
            }
            out.graph.simplices.swap(simplices);
        };
    detail::TriangulationResult tri =
        dim == 2 ? detail::triangulate_and_locate_2d(points, vertex_node, query_nodes, visit_order, locate_progress,
                                                     beside_locate)
                 : detail::triangulate_and_locate_3d(points, vertex_node, query_nodes, visit_order, locate_progress,
                                                     beside_locate);
    out.graph.simplices = std::move(tri.simplices);
    out.location = std::move(tri.location);
    out.timings = tri.timings;
    out.timings.triangulate_seconds += group_seconds;
    out.timings.spatially_sorted = spatial;
    return out;
}

}  // namespace dgwarp
