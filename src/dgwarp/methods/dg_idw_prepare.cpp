// prepare_dg_idw: the Delaunay graph, point location and per-corner coefficients.
#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "dgwarp/core/error.hpp"
#include "dgwarp/core/parallel_for.hpp"
#include "dgwarp/core/stopwatch.hpp"
#include "dgwarp/graph/delaunay_graph.hpp"
#include "dgwarp/methods/dg_idw.hpp"
#include "dgwarp/methods/dg_idw_checks.hpp"

namespace dgwarp {

namespace {

// A volume node closer than this fraction of the boundary's bounding-box
// diagonal to a graph vertex takes that vertex's motion: u = 1/r would
// overflow or dominate anyway, and this keeps q finite.
constexpr double snap_fraction = 1e-12;

void check_boundary_set(std::size_t num_points, const BoundarySet& boundary) {
    if (boundary.moving.size() != boundary.nodes.size())
        throw MeshError("the boundary set has " + std::to_string(boundary.nodes.size()) + " nodes but " +
                        std::to_string(boundary.moving.size()) + " moving flags");
    for (std::size_t b = 0; b < boundary.nodes.size(); ++b) {
        const NodeId n = boundary.nodes[b];
        if (n < 0 || static_cast<std::size_t>(n) >= num_points)
            throw MeshError("boundary node id " + std::to_string(n) + " is out of range (the mesh has " +
                                std::to_string(num_points) + " points)",
                            {}, n);
        if (b > 0 && n <= boundary.nodes[b - 1])
            throw MeshError("boundary node ids must be sorted and unique; node " + std::to_string(n) +
                                " follows node " + std::to_string(boundary.nodes[b - 1]),
                            {}, n);
        if (boundary.moving[b] > 1)
            throw MeshError("boundary node " + std::to_string(n) + " has moving flag " +
                                std::to_string(int(boundary.moving[b])) + " (expected 0 or 1)",
                            {}, n);
    }
}

// Bounding-box diagonal of the boundary nodes with moving flag `moving`
// (any flag when `any`); 0 when there are none.
double bounding_diagonal(int dim, std::span<const double> points, const BoundarySet& boundary, bool any) {
    double lo[3] = {std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity(),
                    std::numeric_limits<double>::infinity()};
    double hi[3] = {-lo[0], -lo[1], -lo[2]};
    bool found = false;
    for (std::size_t b = 0; b < boundary.nodes.size(); ++b) {
        if (!any && !boundary.moving[b]) continue;
        found = true;
        for (int d = 0; d < dim; ++d) {
            const double x = points[static_cast<std::size_t>(boundary.nodes[b]) * dim + d];
            lo[d] = std::min(lo[d], x);
            hi[d] = std::max(hi[d], x);
        }
    }
    if (!found) return 0;
    double s = 0;
    for (int d = 0; d < dim; ++d) s += (hi[d] - lo[d]) * (hi[d] - lo[d]);
    return std::sqrt(s);
}

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
        for (int k = 0; k < corners; ++k) q[k] = k == nearest && moving[k] ? 1.0 : 0.0;
        return true;
    }
    if (n_moving == 0) {
        for (int k = 0; k < corners; ++k) q[k] = 0.0;
        return false;
    }
    const double m = n_moving == dim ? double(dim) : n_moving == 1 ? 1.0 / dim : 1.0;
    double p_sum = 0;
    for (int k = 0; k < corners; ++k)
        if (moving[k]) p_sum += 1.0 / (r[k] * r[k]);
    for (int k = 0; k < corners; ++k) q[k] = moving[k] ? 1.0 / (r[k] * r[k]) / p_sum : -(m / r[k]) / p_sum;
    return false;
}

}  // namespace

DgIdwPlan prepare_dg_idw(int dim, std::span<const double> points, const BoundarySet& boundary,
                         const DgIdwOptions& options) {
    if (dim != 2 && dim != 3) throw MeshError("DG-IDW needs dim 2 or 3, got " + std::to_string(dim));
    if (points.size() % static_cast<std::size_t>(dim) != 0)
        throw MeshError("the point array holds " + std::to_string(points.size()) +
                        " values, not a whole number of " + std::to_string(dim) + "D points");
    const std::size_t num_points = points.size() / static_cast<std::size_t>(dim);
    if (num_points > static_cast<std::size_t>(std::numeric_limits<std::int32_t>::max()))
        throw MeshError("the mesh has " + std::to_string(num_points) + " points, more than int32 node ids can hold");
    check_dg_idw_options(options);
    check_boundary_set(num_points, boundary);

    DgIdwPlan plan;
    plan.dim = dim;
    plan.boundary_nodes = boundary.nodes;
    plan.boundary_moving = boundary.moving;
    const double moving_diagonal = bounding_diagonal(dim, points, boundary, false);
    const double boundary_diagonal = bounding_diagonal(dim, points, boundary, true);
    plan.auto_length_scale = moving_diagonal > 0 ? moving_diagonal : boundary_diagonal > 0 ? boundary_diagonal : 1.0;

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
    std::vector<std::int32_t> vertex_motion(g.num_vertices());
    for (std::size_t v = 0; v < g.num_vertices(); ++v) {
        const auto first = g.vertex_nodes.begin() + g.vertex_offsets[v];
        const auto last = g.vertex_nodes.begin() + g.vertex_offsets[v + 1];
        const auto mover = std::find_if(first, last, [&](std::int32_t b) { return boundary.moving[b] != 0; });
        vertex_motion[v] = mover != last ? *mover : -1 - *first;
        if (last - first > 1) {
            plan.shared_members.insert(plan.shared_members.end(), first, last);
            plan.shared_offsets.push_back(static_cast<std::int32_t>(plan.shared_members.size()));
        }
    }
    plan.stats.shared_vertex_count = static_cast<std::int64_t>(plan.shared_offsets.size()) - 1;
    plan.stats.graph_vertex_count = static_cast<std::int64_t>(g.num_vertices());
    const int corners = dim + 1;
    // Keep only the simplices that hold a volume node, numbered in order of
    // first use by the nodes: deform then reads the simplex table almost
    // sequentially instead of at random (and the plan is smaller). Each row
    // lists its moving corners first, so deform needs no per-corner branch.
    std::vector<std::int32_t> renumbered(g.num_simplices(), -1);
    std::int32_t used = 0;
    for (std::int32_t& s : lg.location.simplex) {
        if (renumbered[s] < 0) {
            renumbered[s] = used++;
            const std::size_t row = plan.simplex_motion.size();
            for (int k = 0; k < corners; ++k)
                plan.simplex_motion.push_back(vertex_motion[g.simplices[static_cast<std::size_t>(s) * corners + k]]);
            std::stable_partition(plan.simplex_motion.begin() + row, plan.simplex_motion.end(),
                                  [](std::int32_t b) { return b >= 0; });
        }
        s = renumbered[s];
    }

    const double snap_distance = snap_fraction * boundary_diagonal;
    plan.node_coefficients.resize(volume.size() * static_cast<std::size_t>(corners));
    std::vector<std::uint8_t> snapped(volume.size(), 0);
    parallel_for(static_cast<std::int64_t>(volume.size()), [&](std::int64_t i) {
        const std::int32_t* corner =
            plan.simplex_motion.data() + static_cast<std::size_t>(lg.location.simplex[i]) * corners;
        const double* p[4];
        bool moving[4];
        for (int k = 0; k < corners; ++k) {
            const std::int32_t b = corner[k];
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
