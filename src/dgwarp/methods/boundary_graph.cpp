#include "dgwarp/methods/boundary_graph.hpp"

#include "dgwarp/methods/method_inputs.hpp"

namespace dgwarp {

BoundaryGraph build_boundary_graph(int dim, std::span<const double> points, const BoundarySet& boundary,
                                   std::size_t num_points, std::vector<std::int32_t>& node_simplex,
                                   const ProgressFn& progress, const std::function<void()>& beside_build) {
    BoundaryGraph g;
    g.volume = split_volume_nodes(num_points, boundary, node_simplex);
    GraphOptions options;
    options.beside_build = beside_build;
    g.located = build_located_graph(dim, points, boundary.nodes, g.volume, options, progress);
    g.vertex_motion = graph_vertex_motion(g.located.graph, boundary.moving);
    return g;
}

}  // namespace dgwarp
