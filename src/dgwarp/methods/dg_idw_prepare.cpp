// prepare_dg_idw: the Delaunay graph, point location and per-corner coefficients.
#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "dgwarp/core/error.hpp"
#include "dgwarp/core/parallel_for.hpp"
#include "dgwarp/core/stopwatch.hpp"
#include "dgwarp/graph/barycentric.hpp"
#include "dgwarp/methods/boundary_graph.hpp"
#include "dgwarp/methods/boundary_set_tools.hpp"
#include "dgwarp/methods/dg_idw.hpp"
#include "dgwarp/methods/dg_idw_checks.hpp"
#include "dgwarp/methods/method_inputs.hpp"

namespace dgwarp {

namespace {

// A volume node closer than this fraction of the boundary's bounding-box
// diagonal to a graph vertex takes that vertex's motion: u = 1/r would
// overflow or dominate anyway, and this keeps q finite.
constexpr double snap_fraction = 1e-12;

// The gap between the moving and the static boundary: the shortest distance
// from a moving to a static graph vertex (infinity when either set is empty).
// The closest such pair is always a graph edge (the ball with the pair as
// diameter holds no other point, or that point would make a closer
// moving-static pair), so scanning the simplices' edges finds it exactly.
double moving_static_gap(int dim, std::span<const double> points, std::span<const NodeId> boundary_nodes,
                         std::span<const std::int32_t> simplices, std::span<const std::int32_t> vertex_motion) {
    const int corners = dim + 1;
    auto coordinates = [&](std::int32_t v) {
        const std::int32_t b = vertex_motion[v] >= 0 ? vertex_motion[v] : -1 - vertex_motion[v];
        return points.data() + static_cast<std::size_t>(boundary_nodes[b]) * dim;
    };
    double gap2 = std::numeric_limits<double>::infinity();
    for (std::size_t s = 0; s < simplices.size(); s += corners)
        for (int i = 0; i < corners; ++i)
            for (int j = i + 1; j < corners; ++j) {
                const std::int32_t u = simplices[s + i], v = simplices[s + j];
                if ((vertex_motion[u] >= 0) == (vertex_motion[v] >= 0)) continue;
                const double *p = coordinates(u), *q = coordinates(v);
                double d2 = 0;
                for (int d = 0; d < dim; ++d) d2 += (p[d] - q[d]) * (p[d] - q[d]);
                gap2 = std::min(gap2, d2);
            }
    return std::sqrt(gap2);
}

// Coefficients of one volume node at x0 in a simplex with corners p[k]
// (moving[k]): see dg_idw.hpp. Returns true when the node was snapped.
bool corner_coefficients(int dim, const double* x0, const double* const* p, const bool* moving,
                         DgIdwWeighting weighting, double snap_distance, double* q) {
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
    // e: the barycentric damping of the continuous weighting (1 for the
    // paper's). Clamped at 0: a node outside the hull is in the nearest
    // simplex, where a coordinate can be negative.
    double e[4] = {1, 1, 1, 1};
    double m = n_moving == dim ? double(dim) : n_moving == 1 ? 1.0 / dim : 1.0;
    if (weighting == DgIdwWeighting::continuous) {
        barycentric(dim, x0, p, e);
        for (int k = 0; k < corners; ++k) e[k] = std::max(0.0, e[k]);
        m = 1.0;
    }
    double p_sum = 0;
    for (int k = 0; k < corners; ++k)
        if (moving[k]) p_sum += e[k] / (r[k] * r[k]);
    if (p_sum == 0) {  // on a face of static corners only: the node stays
        for (int k = 0; k < corners; ++k) q[k] = 0.0;
        return false;
    }
    for (int k = 0; k < corners; ++k)
        q[k] = moving[k] ? e[k] / (r[k] * r[k]) / p_sum : -(e[k] * m / r[k]) / p_sum;
    return false;
}

}  // namespace

const char* weighting_name(DgIdwWeighting w) {
    return w == DgIdwWeighting::continuous ? "continuous" : "paper";
}

DgIdwPlan prepare_dg_idw(int dim, std::span<const double> points, const BoundarySet& boundary,
                         const DgIdwOptions& options, const ProgressFn& progress) {
    const std::size_t num_points = check_points_and_boundary("DG-IDW", dim, points, boundary);
    check_dg_idw_options(options);

    DgIdwPlan plan;
    plan.dim = dim;
    plan.options = options;
    plan.boundary_nodes = boundary.nodes;
    plan.boundary_moving = boundary.moving;
    const double moving_diagonal = boundary_diagonal(dim, points, boundary, true);
    const double all_diagonal = boundary_diagonal(dim, points, boundary, false);

    // Beside the graph's (serial) build: the per-node arrays, allocated and
    // zeroed, the boundary points and the mesh's fingerprint.
    const int corners = dim + 1;
    const std::size_t num_volume_nodes = num_points - boundary.nodes.size();
    std::vector<std::uint8_t> snapped;
    std::vector<double> boundary_points;
    const auto beside_build = [&] {
        plan.node_coefficients.resize(num_volume_nodes * static_cast<std::size_t>(corners));
        snapped.assign(num_volume_nodes, 0);
        // The boundary points by boundary index, in one small array (it stays in cache).
        boundary_points = gather_points(dim, points, boundary.nodes);
        plan.mesh = mesh_fingerprint(dim, points, boundary);
    };
    BoundaryGraph bg = prepare_boundary_graph(plan, dim, points, boundary, num_points,
                                              progress_part(progress, 0, 0.9), beside_build);
    const std::vector<NodeId>& volume = bg.volume;
    LocatedGraph& lg = bg.located;
    const std::vector<std::int32_t>& vertex_motion = bg.vertex_motion.vertex_motion;

    const auto t0 = Clock::now();
    const DelaunayGraph& g = lg.graph;
    plan.stats.graph_vertex_count = static_cast<std::int64_t>(g.num_vertices());
    plan.stats.graph_simplex_count = static_cast<std::int64_t>(g.num_simplices());

    // Auto length scale (dg_idw.hpp): the moving boundary's size, but small
    // enough that the zone following the moving boundary, a L, fits in the gap.
    const double size = moving_diagonal > 0 ? moving_diagonal : all_diagonal > 0 ? all_diagonal : 1.0;
    double gap = 0;
    run_concurrently(
        [&] {
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
                        plan.simplex_motion.push_back(
                            vertex_motion[g.simplices[static_cast<std::size_t>(s) * corners + k]]);
                    std::stable_partition(plan.simplex_motion.begin() + row, plan.simplex_motion.end(),
                                          [](std::int32_t b) { return b >= 0; });
                }
                s = renumbered[s];
            }
        },
        [&] { gap = moving_static_gap(dim, points, plan.boundary_nodes, g.simplices, vertex_motion); });
    plan.auto_length_scale = std::min(size, gap / std::max(options.a_translation, options.a_rotation));

    const double snap_distance = snap_fraction * all_diagonal;
    // Each node's simplex row is asked for ahead: in a spatially random
    // numbering the rows are far apart (as in deform, dg_idw_deform.cpp).
    constexpr std::int64_t row_ahead = 16;
    const auto num_volume = static_cast<std::int64_t>(volume.size());
    parallel_for(num_volume, [&](std::int64_t i) {
        if (i + row_ahead < num_volume)
            __builtin_prefetch(plan.simplex_motion.data() +
                               static_cast<std::size_t>(lg.location.simplex[i + row_ahead]) * corners);
        const std::int32_t* corner =
            plan.simplex_motion.data() + static_cast<std::size_t>(lg.location.simplex[i]) * corners;
        const double* p[4];
        bool moving[4];
        for (int k = 0; k < corners; ++k) {
            const std::int32_t b = corner[k];
            moving[k] = b >= 0;
            p[k] = boundary_points.data() + static_cast<std::size_t>(b >= 0 ? b : -1 - b) * dim;
        }
        plan.node_simplex[volume[i]] = lg.location.simplex[i];
        snapped[i] = corner_coefficients(dim, points.data() + static_cast<std::size_t>(volume[i]) * dim, p, moving,
                                         options.weighting, snap_distance, plan.node_coefficients.data() + i * corners);
    });
    plan.stats.snapped_count = std::count(snapped.begin(), snapped.end(), std::uint8_t{1});
    plan.stats.weights_seconds = seconds_since(t0);
    if (progress) progress(1.0);
    return plan;
}

}  // namespace dgwarp
