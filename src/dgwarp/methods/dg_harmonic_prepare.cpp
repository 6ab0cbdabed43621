// prepare_dg_harmonic: coarse points, coarse graph, location, factorised Laplacian.
#include <algorithm>
#include <cmath>
#include <string>

#include "dgwarp/core/error.hpp"
#include "dgwarp/core/stopwatch.hpp"
#include "dgwarp/core/parallel_for.hpp"
#include "dgwarp/graph/delaunay_graph.hpp"
#include "dgwarp/graph/morton_order.hpp"
#include "dgwarp/graph/nearest_node.hpp"
#include "dgwarp/methods/boundary_set_tools.hpp"
#include "dgwarp/methods/coarse_laplacian.hpp"
#include "dgwarp/methods/coarse_points.hpp"
#include "dgwarp/methods/dg_harmonic_on_coarse.hpp"
#include "dgwarp/methods/dg_harmonic.hpp"
#include "dgwarp/methods/dg_harmonic_guard.hpp"
#include "dgwarp/methods/dgm_detail.hpp"
#include "dgwarp/methods/graph_vertex_motion.hpp"
#include "dgwarp/methods/method_inputs.hpp"

namespace dgwarp {

namespace {

// The edges of the coarse graph that touch an unknown, as (u, v) with u < v,
// sorted; first[u] .. first[u + 1] are the edges whose smaller end is u (so
// that an edge's index is found among a vertex's few edges, not by a search
// of all of them: 1.45 M look-ups at 826k).
struct UnknownEdges {
    std::vector<std::pair<std::int32_t, std::int32_t>> list;
    std::vector<std::int64_t> first;  // num_vertices + 1

    std::int64_t index(std::int32_t u, std::int32_t v) const {
        const auto begin = list.begin() + first[u], end = list.begin() + first[u + 1];
        return std::lower_bound(begin, end, std::pair{u, v}) - list.begin();
    }
};

UnknownEdges unknown_edges(int dim, std::span<const std::int32_t> simplices, std::int32_t first_unknown,
                           std::size_t num_vertices) {
    const int corners = dim + 1;
    auto for_each_pair = [&](auto&& f) {
        for (std::size_t s = 0; s < simplices.size(); s += corners)
            for (int i = 0; i < corners; ++i)
                for (int j = i + 1; j < corners; ++j) {
                    std::int32_t u = simplices[s + i], v = simplices[s + j];
                    if (u > v) std::swap(u, v);
                    if (v >= first_unknown) f(u, v);
                }
    };
    // Bucket the larger ends by the smaller end (with repeats), then sort and
    // deduplicate each bucket: the list comes out in (u, v) order.
    std::vector<std::int64_t> start(num_vertices + 1, 0);
    for_each_pair([&](std::int32_t u, std::int32_t) { ++start[static_cast<std::size_t>(u) + 1]; });
    for (std::size_t u = 0; u < num_vertices; ++u) start[u + 1] += start[u];
    std::vector<std::int32_t> bucket(static_cast<std::size_t>(start[num_vertices]));
    std::vector<std::int64_t> fill(start.begin(), start.end() - 1);
    for_each_pair([&](std::int32_t u, std::int32_t v) { bucket[static_cast<std::size_t>(fill[u]++)] = v; });
    UnknownEdges e;
    e.first.assign(num_vertices + 1, 0);
    e.list.reserve(bucket.size() / 2);
    for (std::size_t u = 0; u < num_vertices; ++u) {
        const auto b = bucket.begin() + start[u], end = bucket.begin() + start[u + 1];
        std::sort(b, end);
        for (auto it = b; it != end; ++it)
            if (it == b || *it != *(it - 1)) e.list.emplace_back(static_cast<std::int32_t>(u), *it);
        e.first[u + 1] = static_cast<std::int64_t>(e.list.size());
    }
    return e;
}

// Per coarse graph vertex, its distances to the nearest moving and the nearest
// static boundary node (0 for a boundary vertex of that kind).
struct WallDistances {
    std::vector<double> moving, fixed;
};

WallDistances wall_distances(int dim, std::span<const double> points, const BoundarySet& boundary,
                             std::span<const NodeId> vertex_node) {
    std::vector<NodeId> moving_nodes, static_nodes;
    for (std::size_t b = 0; b < boundary.nodes.size(); ++b)
        (boundary.moving[b] ? moving_nodes : static_nodes).push_back(boundary.nodes[b]);
    const NearestNode moving(dim, points, moving_nodes), fixed(dim, points, static_nodes);
    WallDistances w;
    w.moving.resize(vertex_node.size());
    w.fixed.resize(vertex_node.size());
    parallel_for(static_cast<std::int64_t>(vertex_node.size()), [&](std::int64_t v) {
        const double* x = points.data() + static_cast<std::size_t>(vertex_node[v]) * dim;
        w.moving[v] = moving.nearest(x).distance;
        w.fixed[v] = fixed.nearest(x).distance;
    });
    return w;
}

// Rigid-zone factor of the rotation's conductivity at a point with distances
// dm, ds to the nearest moving and static boundary nodes.
double rigid_factor(const DgHarmonicOptions& o, double dm, double ds, double moving_diagonal) {
    const double rho = std::min(*o.rigid_zone * moving_diagonal, o.rigid_gap * ds);
    if (!(rho > 0) || !std::isfinite(rho)) return 1.0;
    return 1.0 + std::min((rho / dm) * (rho / dm), 1e6);
}

// The weights of the two systems per edge: the P1 finite-element stiffness
// of the coarse graph (-K_ij summed over the simplices around edge ij), with
// conductivity size^-exponent per simplex (size: its mean edge length) and,
// for the rotation, the rigid-zone factor at its centroid; negative sums
// (possible on 3D slivers) are set to 0, so that the matrix keeps the
// discrete maximum principle.
void edge_weights(const DgHarmonicPlan& plan, std::span<const std::int32_t> simplices, const UnknownEdges& edges,
                  std::span<const double> vertex_xyz, const WallDistances& wall, double moving_diagonal,
                  std::vector<double>& translation, std::vector<double>& rotation) {
    const int dim = plan.dim, corners = dim + 1;
    const DgHarmonicOptions& o = plan.options;
    const std::int32_t nb = plan.num_boundary_vertices;
    translation.assign(edges.list.size(), 0.0);
    rotation.assign(edges.list.size(), 0.0);
    for (std::size_t s = 0; s < simplices.size(); s += corners) {
        const std::int32_t* c = simplices.data() + s;
        bool has_unknown = false;
        for (int k = 0; k < corners; ++k) has_unknown |= c[k] >= nb;
        if (!has_unknown) continue;
        const double* p[4];
        for (int k = 0; k < corners; ++k) p[k] = vertex_xyz.data() + static_cast<std::size_t>(c[k]) * dim;
        // Gradients of the barycentric functions: G = J^-1, J = [p1 - p0, ...].
        double j[3][3] = {}, g[4][3] = {};
        for (int k = 1; k < corners; ++k)
            for (int d = 0; d < dim; ++d) j[d][k - 1] = p[k][d] - p[0][d];
        double det;
        if (dim == 2) {
            det = j[0][0] * j[1][1] - j[0][1] * j[1][0];
            if (det == 0) continue;
            // rows of J^-1 are the gradients of phi_1, phi_2
            g[1][0] = j[1][1] / det, g[1][1] = -j[0][1] / det;
            g[2][0] = -j[1][0] / det, g[2][1] = j[0][0] / det;
        } else {
            const double c00 = j[1][1] * j[2][2] - j[1][2] * j[2][1], c01 = j[1][2] * j[2][0] - j[1][0] * j[2][2],
                         c02 = j[1][0] * j[2][1] - j[1][1] * j[2][0];
            det = j[0][0] * c00 + j[0][1] * c01 + j[0][2] * c02;
            if (det == 0) continue;
            // (J^-1)_{r,d} = cofactor(d, r) / det
            const double inv[3][3] = {
                {c00 / det, (j[0][2] * j[2][1] - j[0][1] * j[2][2]) / det, (j[0][1] * j[1][2] - j[0][2] * j[1][1]) / det},
                {c01 / det, (j[0][0] * j[2][2] - j[0][2] * j[2][0]) / det, (j[0][2] * j[1][0] - j[0][0] * j[1][2]) / det},
                {c02 / det, (j[0][1] * j[2][0] - j[0][0] * j[2][1]) / det, (j[0][0] * j[1][1] - j[0][1] * j[1][0]) / det}};
            for (int k = 1; k < 4; ++k)
                for (int d = 0; d < 3; ++d) g[k][d] = inv[k - 1][d];
        }
        for (int d = 0; d < dim; ++d) {
            g[0][d] = 0;
            for (int k = 1; k < corners; ++k) g[0][d] -= g[k][d];
        }
        const double volume = std::abs(det) / (dim == 2 ? 2.0 : 6.0);
        double size = 0, dm = 0, ds = 0;
        int pairs = 0;
        for (int a = 0; a < corners; ++a) {
            if (!wall.moving.empty()) {
                dm += wall.moving[c[a]] / corners;
                ds += wall.fixed[c[a]] / corners;
            }
            for (int b = a + 1; b < corners; ++b, ++pairs) {
                double l2 = 0;
                for (int d = 0; d < dim; ++d) l2 += (p[a][d] - p[b][d]) * (p[a][d] - p[b][d]);
                size += std::sqrt(l2);
            }
        }
        size /= pairs;
        dm = std::max(dm, 0.5 * size);
        const double kt = *o.translation_exponent == 0 ? 1.0 : std::pow(size, -*o.translation_exponent);
        const double kr = (*o.rotation_exponent == *o.translation_exponent ? kt
                           : *o.rotation_exponent == 0                     ? 1.0
                                                                           : std::pow(size, -*o.rotation_exponent)) *
                          rigid_factor(o, dm, ds, moving_diagonal);
        for (int a = 0; a < corners; ++a)
            for (int b = a + 1; b < corners; ++b) {
                std::int32_t u = c[a], v = c[b];
                if (u > v) std::swap(u, v);
                if (v < nb) continue;
                double kab = 0;
                for (int d = 0; d < dim; ++d) kab += g[a][d] * g[b][d];
                const double w = -volume * kab;
                const std::int64_t e = edges.index(u, v);
                translation[e] += kt * w;
                rotation[e] += kr * w;
            }
    }
    for (std::size_t e = 0; e < edges.list.size(); ++e) {
        translation[e] = std::max(translation[e], 0.0);
        rotation[e] = std::max(rotation[e], 0.0);
    }
}

// Barycentric coordinates clamped at 0 and scaled to sum 1 (a node outside
// the hull takes the motion of the nearest point of its simplex).
void clamp_barycentric(int dim, std::vector<double>& e) {
    const int corners = dim + 1;
    for (std::size_t i = 0; i < e.size(); i += corners) {
        double sum = 0;
        for (int k = 0; k < corners; ++k) {
            e[i + k] = std::max(e[i + k], 0.0);
            sum += e[i + k];
        }
        for (int k = 0; k < corners; ++k) e[i + k] /= sum;
    }
}

}  // namespace

void check_dg_harmonic_options(const DgHarmonicOptions& options) {
    if (!std::isfinite(options.wall_spacing) || options.wall_spacing <= 0)
        throw Error("DG-harmonic: wall_spacing must be finite and positive, got " + std::to_string(options.wall_spacing));
    if (!std::isfinite(options.growth) || options.growth <= 0)
        throw Error("DG-harmonic: growth must be finite and positive, got " + std::to_string(options.growth));
    for (const auto& [name, value] : {std::pair{"translation_exponent", options.translation_exponent},
                                      std::pair{"rotation_exponent", options.rotation_exponent}})
        if (value && !(*value >= 0 && *value <= 4))
            throw Error(std::string("DG-harmonic: ") + name + " must be 0 to 4 (unset: the default), got " +
                        std::to_string(*value));
    if (options.rigid_zone && !(std::isfinite(*options.rigid_zone) && *options.rigid_zone >= 0))
        throw Error("DG-harmonic: rigid_zone must be finite and >= 0 (unset: the default), got " +
                    std::to_string(*options.rigid_zone));
    if (!std::isfinite(options.rigid_gap))
        throw Error("DG-harmonic: rigid_gap must be finite, got " + std::to_string(options.rigid_gap));
    if (!(options.redo_max_nodes_3d >= 0))
        throw Error("DG-harmonic: redo_max_nodes_3d must not be negative, got " +
                    std::to_string(options.redo_max_nodes_3d));
    if (!(options.redo_max_increments >= 1 && options.redo_max_increments <= 64))
        throw Error("DG-harmonic: redo_max_increments must be 1 to 64, got " + std::to_string(options.redo_max_increments));
    if (std::isnan(options.redo_below) || options.redo_below >= 1)
        throw Error("DG-harmonic: redo_below must be below 1 (a fraction of the original minimum quality; negative: "
                    "never redo), got " + std::to_string(options.redo_below));
}

DgHarmonicOptions resolved_options(const DgHarmonicOptions& options, int dim) {
    DgHarmonicOptions o = options;
    if (!o.translation_exponent) o.translation_exponent = dim == 2 ? 3 : 2.5;
    if (!o.rotation_exponent) o.rotation_exponent = dim == 2 ? 0 : 2.5;
    if (!o.rigid_zone) o.rigid_zone = dim == 2 ? 0.25 : 0;
    if (o.rigid_gap < 0) o.rigid_gap = 0.5;
    return o;
}

DgHarmonicPlan prepare_dg_harmonic(int dim, std::span<const double> points, const BoundarySet& boundary,
                                   const DgHarmonicOptions& options, const ProgressFn& progress) {
    const std::size_t num_points = check_points_and_boundary("DG-harmonic", dim, points, boundary);
    check_dg_harmonic_options(options);
    std::vector<std::int32_t> node_simplex;
    const std::vector<NodeId> volume = split_volume_nodes(num_points, boundary, node_simplex);
    const auto t0 = Clock::now();
    // The coarse selection and the location both visit the volume nodes along
    // a Morton curve when their numbering is not spatially coherent: sorted once.
    const std::vector<std::uint32_t> morton =
        is_coherent_order(dim, points, volume) ? std::vector<std::uint32_t>{} : morton_order(dim, points, volume);
    const std::vector<NodeId> coarse =
        select_coarse_points(dim, points, boundary.nodes, volume, {options.wall_spacing, options.growth}, morton);
    const double select_seconds = seconds_since(t0);
    if (progress) progress(0.1);
    DgHarmonicPlan plan = prepare_dg_harmonic_on_coarse(dim, points, boundary, coarse, options, progress, morton);
    plan.stats.select_seconds = select_seconds;
    return plan;
}

DgHarmonicPlan prepare_dg_harmonic_on_coarse(int dim, std::span<const double> points, const BoundarySet& boundary,
                                             std::span<const NodeId> coarse, const DgHarmonicOptions& options,
                                             const ProgressFn& progress, std::span<const std::uint32_t> volume_morton) {
    const std::size_t num_points = check_points_and_boundary("DG-harmonic", dim, points, boundary);
    check_dg_harmonic_options(options);

    DgHarmonicPlan plan;
    plan.dim = dim;
    plan.options = resolved_options(options, dim);
    plan.mesh = mesh_fingerprint(dim, points, boundary);
    plan.boundary_nodes = boundary.nodes;
    plan.boundary_moving = boundary.moving;
    const std::vector<NodeId> volume = split_volume_nodes(num_points, boundary, plan.node_simplex);
    auto t0 = Clock::now();

    // Graph points: the boundary nodes (boundary indices 0..nb-1), then the
    // coarse volume nodes. Graph vertices are numbered by their smallest
    // index, so the boundary vertices come first.
    std::vector<NodeId> graph_nodes(boundary.nodes);
    graph_nodes.insert(graph_nodes.end(), coarse.begin(), coarse.end());
    // What needs the graph but not the location (the vertices' motion, the
    // coarse Laplacian's weights and factors), beside the location.
    std::vector<NodeId> vertex_node;
    const auto on_graph = [&](const DelaunayGraph& g) {
        const auto t = Clock::now();
        std::vector<std::uint8_t> moving(boundary.moving);
        moving.resize(graph_nodes.size(), 0);
        GraphVertexMotion vm = graph_vertex_motion(g, moving);
        const auto nb_index = static_cast<std::int32_t>(boundary.nodes.size());
        plan.num_boundary_vertices = 0;
        while (static_cast<std::size_t>(plan.num_boundary_vertices) < g.num_vertices() &&
               g.vertex_nodes[g.vertex_offsets[plan.num_boundary_vertices]] < nb_index)
            ++plan.num_boundary_vertices;
        plan.vertex_motion = std::move(vm.vertex_motion);
        // Shared groups of boundary points only: two coarse volume nodes at the
        // same coordinates are one interior vertex and have no motion to share.
        for (std::size_t grp = 0; grp + 1 < vm.shared_offsets.size(); ++grp) {
            const std::int32_t first = vm.shared_members[vm.shared_offsets[grp]];
            if (first >= nb_index) continue;
            for (std::int32_t k = vm.shared_offsets[grp]; k < vm.shared_offsets[grp + 1]; ++k)
                if (vm.shared_members[k] < nb_index) plan.shared_members.push_back(vm.shared_members[k]);
            plan.shared_offsets.push_back(static_cast<std::int32_t>(plan.shared_members.size()));
        }
        plan.stats.shared_vertex_count = static_cast<std::int64_t>(plan.shared_offsets.size()) - 1;
        plan.stats.graph_vertices = static_cast<std::int64_t>(g.num_vertices());
        plan.stats.coarse_interior = plan.num_vertices() - plan.num_boundary_vertices;
        vertex_node.resize(g.num_vertices());
        for (std::size_t v = 0; v < vertex_node.size(); ++v)
            vertex_node[v] = graph_nodes[g.vertex_nodes[g.vertex_offsets[v]]];
        const std::vector<double> vertex_xyz = gather_points(dim, points, vertex_node);
        if (plan.num_vertices() > plan.num_boundary_vertices) {
            const UnknownEdges edges =
                unknown_edges(dim, g.simplices, plan.num_boundary_vertices, static_cast<std::size_t>(plan.num_vertices()));
            // Without a rigid zone (the 3D default) the distances would weigh
            // nothing: skip their queries (exact nearest-node queries far from a
            // sphere's nodes are slow: 0.2 s of prepare at 202k nodes).
            const WallDistances wall = *plan.options.rigid_zone > 0 ? wall_distances(dim, points, boundary, vertex_node)
                                                                   : WallDistances{};
            std::vector<double> wt, wr;
            edge_weights(plan, g.simplices, edges, vertex_xyz, wall, boundary_diagonal(dim, points, boundary, true), wt,
                         wr);
            const auto n = static_cast<std::int32_t>(plan.num_vertices() - plan.num_boundary_vertices);
            plan.solve = factorise_coarse_laplacian(edges.list, wt, wr, plan.num_boundary_vertices, n,
                                                    &plan.stats.floored_weights);
            plan.stats.factor_nonzeros = static_cast<std::int64_t>(plan.solve.l_row.size());
        }
        plan.stats.factor_seconds = seconds_since(t);
    };
    GraphOptions graph_options{LocateOrder::automatic, volume_morton};
    graph_options.beside_locate = on_graph;
    LocatedGraph lg = build_located_graph(dim, points, graph_nodes, volume, graph_options, progress_part(progress, 0.1, 0.8));
    plan.stats.graph_seconds = lg.timings.triangulate_seconds;
    plan.stats.locate_seconds = lg.timings.locate_seconds;
    plan.stats.outside_count = lg.location.outside_count;

    t0 = Clock::now();
    const DelaunayGraph& g = lg.graph;
    plan.node_barycentric =
        detail::barycentric_coordinates(dim, points, vertex_node, g.simplices, volume, lg.location.simplex);
    clamp_barycentric(dim, plan.node_barycentric);
    for (std::size_t i = 0; i < volume.size(); ++i) plan.node_simplex[volume[i]] = lg.location.simplex[i];
    plan.simplices = std::move(lg.graph.simplices);
    plan.stats.locate_seconds += seconds_since(t0);
    if (progress) progress(1.0);
    return plan;
}

namespace {
std::size_t factor_bytes(const HarmonicFactors& f) {
    std::size_t n = bytes_of(f.perm) + bytes_of(f.l_start) + bytes_of(f.l_row) + bytes_of(f.coupling_start) +
                    bytes_of(f.coupling_vertex);
    for (const auto* s : {&f.translation, &f.rotation}) n += bytes_of(s->l_value) + bytes_of(s->d) + bytes_of(s->coupling_weight);
    return n;
}
}  // namespace

void check_plan_fits(const DgHarmonicPlan& plan, std::span<const double> points, const BoundarySet& boundary) {
    check_fingerprint(plan.mesh, plan.dim, plan.boundary_nodes.size(), points, boundary);
}

std::size_t plan_bytes(const DgHarmonicPlan& p) {
    return sizeof(DgHarmonicPlan) + core_bytes(p) + bytes_of(p.vertex_motion) + bytes_of(p.simplices) +
           bytes_of(p.node_barycentric) + factor_bytes(p.solve) + (p.guard ? guard_bytes(*p.guard) : 0);
}

}  // namespace dgwarp
