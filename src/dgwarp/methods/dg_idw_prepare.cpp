// prepare_dg_idw: the Delaunay graph, point location and per-corner coefficients.
#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "dgwarp/core/error.hpp"
#include "dgwarp/core/parallel_for.hpp"
#include "dgwarp/core/stopwatch.hpp"
#include "dgwarp/graph/delaunay_graph.hpp"
#include "dgwarp/methods/boundary_set_tools.hpp"
#include "dgwarp/methods/dg_idw.hpp"
#include "dgwarp/methods/dg_idw_checks.hpp"

namespace dgwarp {

namespace {

// A volume node closer than this fraction of the boundary's bounding-box
// diagonal to a graph vertex takes that vertex's motion: u = 1/r would
// overflow or dominate anyway, and this keeps q finite.
constexpr double snap_fraction = 1e-12;

// Coefficients of one volume node at x0 in a simplex with corners p[k]
// (moving[k]): see dg_idw.hpp. Returns true when the node was snapped.
bool corner_coefficients(int dim, const double* x0, const double* const* p, const bool* moving,
                         double snap_distance, double* q) {
    const int corners = dim + 1;
    int n_moving = 0;
    for (int k = 0; k < corners; ++k) n_moving += moving[k];
    double r[4] = {};
    int nearest = 0;
    for (int k = 0; k < corners; ++k) {
        double s = 0;
        for (int d = 0; d < dim; ++d) s += (x0[d] - p[k][d]) * (x0[d] - p[k][d]);
        r[k] = std::sqrt(s);
        if (r[k] < r[nearest]) nearest = k;
    }
    if (r[nearest] < snap_distance) {
        for (int k = 0; k < corners; ++k) q[k] = k == nearest ? 1.0 : 0.0;
        return true;
    }
    const double m = n_moving == dim ? double(dim) : n_moving == 1 ? 1.0 / dim : 1.0;
    for (int k = 0; k < corners; ++k) {
        const double u = 1.0 / r[k];
        q[k] = moving[k] ? u * u : m * u;
    }
    return false;
}

}  // namespace

DgIdwPlan prepare_dg_idw(int dim, std::span<const double> points, const BoundarySet& boundary,
                         const DgIdwOptions& options) {
    const std::size_t num_points = checked_point_count("DG-IDW", dim, points);
    check_dg_idw_options(options);
    check_boundary_set(num_points, boundary);

    DgIdwPlan plan;
    plan.dim = dim;
    plan.boundary_nodes = boundary.nodes;
    plan.boundary_moving = boundary.moving;
    const double moving_diagonal = boundary_diagonal(dim, points, boundary, true);
    const double all_diagonal = boundary_diagonal(dim, points, boundary, false);
    plan.auto_length_scale = moving_diagonal > 0 ? moving_diagonal : all_diagonal > 0 ? all_diagonal : 1.0;

    // Volume nodes: every node not in the (sorted) boundary list.
    std::vector<NodeId> volume;
    volume.reserve(num_points - std::min(num_points, boundary.nodes.size()));
    plan.node_simplex.resize(num_points);
    for (std::size_t n = 0, b = 0; n < num_points; ++n) {
        if (b < boundary.nodes.size() && static_cast<std::size_t>(boundary.nodes[b]) == n) {
            plan.node_simplex[n] = -1 - static_cast<std::int32_t>(b++);
        } else {
            volume.push_back(static_cast<NodeId>(n));
        }
    }

    LocatedGraph lg = build_located_graph(dim, points, boundary.nodes, volume);
    plan.stats.graph_seconds = lg.timings.triangulate_seconds;
    plan.stats.locate_seconds = lg.timings.locate_seconds;
    plan.stats.outside_count = lg.location.outside_count;

    const auto t0 = Clock::now();
    const DelaunayGraph& g = lg.graph;
    plan.simplices = std::move(lg.graph.simplices);
    plan.vertex_motion.resize(g.num_vertices());
    for (std::size_t v = 0; v < g.num_vertices(); ++v) {
        const auto first = g.vertex_nodes.begin() + g.vertex_offsets[v];
        const auto last = g.vertex_nodes.begin() + g.vertex_offsets[v + 1];
        const auto mover = std::find_if(first, last, [&](std::int32_t b) { return boundary.moving[b] != 0; });
        plan.vertex_motion[v] = mover != last ? *mover : -1 - *first;
        if (last - first > 1) {
            plan.shared_members.insert(plan.shared_members.end(), first, last);
            plan.shared_offsets.push_back(static_cast<std::int32_t>(plan.shared_members.size()));
        }
    }
    plan.stats.shared_vertex_count = static_cast<std::int64_t>(plan.shared_offsets.size()) - 1;

    const int corners = dim + 1;
    const double snap_distance = snap_fraction * all_diagonal;
    plan.node_coefficients.resize(volume.size() * static_cast<std::size_t>(corners));
    std::vector<std::uint8_t> snapped(volume.size(), 0);
    parallel_for(static_cast<std::int64_t>(volume.size()), [&](std::int64_t i) {
        const std::int32_t* corner = plan.simplices.data() + static_cast<std::size_t>(lg.location.simplex[i]) * corners;
        const double* p[4];
        bool moving[4];
        for (int k = 0; k < corners; ++k) {
            const std::int32_t b = plan.vertex_motion[corner[k]];
            moving[k] = b >= 0;
            p[k] = points.data() + static_cast<std::size_t>(boundary.nodes[b >= 0 ? b : -1 - b]) * dim;
        }
        plan.node_simplex[volume[i]] = lg.location.simplex[i];
        snapped[i] = corner_coefficients(dim, points.data() + static_cast<std::size_t>(volume[i]) * dim, p, moving,
                                         snap_distance, plan.node_coefficients.data() + i * corners);
    });
    plan.stats.snapped_count = std::count(snapped.begin(), snapped.end(), std::uint8_t{1});
    plan.mesh = mesh_fingerprint(dim, points, boundary);
    plan.stats.weights_seconds = seconds_since(t0);
    return plan;
}

}  // namespace dgwarp
