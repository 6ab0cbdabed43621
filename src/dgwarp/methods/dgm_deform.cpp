// deform_dgm: move the graph, check it, map the volume nodes; sub-step when asked.
#include <algorithm>
#include <cmath>
#include <string>

#include "dgwarp/core/error.hpp"
#include "dgwarp/core/parallel_for.hpp"
#include "dgwarp/graph/delaunay_graph.hpp"
#include "dgwarp/graph/simplex_orientation.hpp"
#include "dgwarp/methods/method_inputs.hpp"
#include "dgwarp/methods/dgm.hpp"
#include "dgwarp/methods/dgm_detail.hpp"

namespace dgwarp {

namespace {

// Per boundary index, the boundary index whose motion it follows on the
// graph (the rule of graph_vertex_motion.hpp applied to its vertex), or -1
// when it is static there. Members of a shared vertex get the same source, so
// they stay on one point at every fraction of the motion.
std::vector<std::int32_t> graph_motion_source(const DgmPlan& plan) {
    std::vector<std::int32_t> source(plan.boundary_nodes.size());
    for (std::size_t b = 0; b < source.size(); ++b)
        source[b] = plan.boundary_moving[b] ? static_cast<std::int32_t>(b) : -1;
    for (std::size_t g = 0; g + 1 < plan.shared_offsets.size(); ++g) {
        const auto first = plan.shared_members.begin() + plan.shared_offsets[g];
        const auto last = plan.shared_members.begin() + plan.shared_offsets[g + 1];
        const auto mover = std::find_if(first, last, [&](std::int32_t b) { return plan.boundary_moving[b] != 0; });
        for (auto it = first; it != last; ++it) source[*it] = mover != last ? *mover : -1;
    }
    return source;
}

NodeMotion scaled(const NodeMotion& m, double f) {
    NodeMotion s = m;
    for (int d = 0; d < 3; ++d) {
        s.translation[d] *= f;
        s.rotation[d] *= f;
    }
    return s;
}

// Graph positions of the boundary nodes at fraction f of the motion
// (boundary_nodes.size() × dim): the motion of each node's source scaled by f.
std::vector<double> graph_positions(const DgmPlan& plan, std::span<const double> points, const BoundaryMotion& motion,
                                    std::span<const std::int32_t> source, double f) {
    const int dim = plan.dim;
    std::vector<double> pos(plan.boundary_nodes.size() * static_cast<std::size_t>(dim));
    parallel_for(static_cast<std::int64_t>(plan.boundary_nodes.size()), [&](std::int64_t b) {
        const auto x = points.subspan(static_cast<std::size_t>(plan.boundary_nodes[b]) * dim, dim);
        const auto y = std::span<double>(pos).subspan(static_cast<std::size_t>(b) * dim, dim);
        if (source[b] < 0 || f == 0) std::copy(x.begin(), x.end(), y.begin());
        else apply_motion(f == 1 ? motion[source[b]] : scaled(motion[source[b]], f), x, y);
    });
    return pos;
}

// Per graph vertex, the position of its representative boundary index
// (num_vertices × dim).
std::vector<double> vertex_positions(int dim, std::span<const std::int32_t> representative,
                                     std::span<const double> boundary_positions) {
    std::vector<double> v(representative.size() * static_cast<std::size_t>(dim));
    for (std::size_t i = 0; i < representative.size(); ++i)
        for (int d = 0; d < dim; ++d)
            v[i * dim + d] = boundary_positions[static_cast<std::size_t>(representative[i]) * dim + d];
    return v;
}

std::vector<std::int32_t> plan_representatives(const DgmPlan& plan) {
    std::vector<std::int32_t> rep(plan.vertex_motion.size());
    for (std::size_t v = 0; v < rep.size(); ++v) rep[v] = plan.vertex_motion[v] >= 0 ? plan.vertex_motion[v] : -1 - plan.vertex_motion[v];
    return rep;
}

// Writes every node for the one-step mapping: boundary nodes by their own
// motion, volume node x0 to x0 + sum_k e_k D_k (D: per graph vertex displacement).
template <int Dim>
void map_range(const DgmPlan& plan, const double* x0, const NodeMotion* motion, const double* disp, double* out,
               std::int64_t begin, std::int64_t end) {
    constexpr int Corners = Dim + 1;
    std::int64_t vol = begin - (std::lower_bound(plan.boundary_nodes.begin(), plan.boundary_nodes.end(), begin) -
                                plan.boundary_nodes.begin());
    for (std::int64_t i = begin; i < end; ++i) {
        const double* x = x0 + i * Dim;
        double* y = out + i * Dim;
        const std::int32_t s = plan.node_simplex[i];
        if (s < 0) {
            const std::int32_t b = -1 - s;
            if (plan.boundary_moving[b]) apply_motion(motion[b], std::span<const double>(x, Dim), std::span<double>(y, Dim));
            else std::copy(x, x + Dim, y);
            continue;
        }
        const double* e = plan.node_barycentric.data() + vol * Corners;
        ++vol;
        const std::int32_t* c = plan.simplices.data() + static_cast<std::int64_t>(s) * Corners;
        double t[Dim] = {};
        for (int k = 0; k < Corners; ++k)
            for (int d = 0; d < Dim; ++d) t[d] += e[k] * disp[c[k] * Dim + d];
        for (int d = 0; d < Dim; ++d) y[d] = x[d] + t[d];
    }
}

void write_one_step(const DgmPlan& plan, std::span<const double> points, const BoundaryMotion& motion,
                    std::span<const double> disp, std::span<double> out) {
    parallel_for_chunks(plan.num_points(), [&](std::int64_t begin, std::int64_t end) {
        if (plan.dim == 2) map_range<2>(plan, points.data(), motion.data(), disp.data(), out.data(), begin, end);
        else map_range<3>(plan, points.data(), motion.data(), disp.data(), out.data(), begin, end);
    });
}

// One increment of the sub-stepped mapping: volume node i (node id volume[i],
// position in `current`) moves by sum_k e_k D_k in its simplex.
void advance_volume(int dim, std::span<const std::int32_t> simplices, std::span<const std::int32_t> volume_simplex,
                    std::span<const double> barycentric, std::span<const double> disp, std::span<const NodeId> volume,
                    std::span<double> current) {
    const int corners = dim + 1;
    parallel_for(static_cast<std::int64_t>(volume.size()), [&](std::int64_t i) {
        const std::int32_t* c = simplices.data() + static_cast<std::size_t>(volume_simplex[i]) * corners;
        const double* e = barycentric.data() + static_cast<std::size_t>(i) * corners;
        double* y = current.data() + static_cast<std::size_t>(volume[i]) * dim;
        double t[3] = {};
        for (int k = 0; k < corners; ++k)
            for (int d = 0; d < dim; ++d) t[d] += e[k] * disp[static_cast<std::size_t>(c[k]) * dim + d];
        for (int d = 0; d < dim; ++d) y[d] += t[d];
    });
}

struct SubstepResult {
    bool valid = false;
    std::int64_t invalid_simplices = 0;  // in the first increment whose moved graph was invalid
    std::int64_t num_simplices = 0;      // of that graph
    int increment = 0;                   // 1-based, of that increment
};

// Maps the volume nodes in k increments into `current` (num_points × dim,
// starting as the original points); stops at the first invalid moved graph.
SubstepResult map_in_increments(const DgmPlan& plan, std::span<const double> points, const BoundaryMotion& motion,
                                std::span<const std::int32_t> source, std::span<const NodeId> volume, int k,
                                std::vector<double>& current) {
    const int dim = plan.dim;
    current.assign(points.begin(), points.end());
    std::vector<double> previous = graph_positions(plan, points, motion, source, 0.0);
    std::vector<std::int32_t> volume_simplex(volume.size());
    for (std::size_t i = 0; i < volume.size(); ++i) volume_simplex[i] = plan.node_simplex[volume[i]];
    for (int j = 1; j <= k; ++j) {
        const double f = j == k ? 1.0 : double(j) / double(k);
        const std::vector<double> next = graph_positions(plan, points, motion, source, f);
        // The graph of the boundary where it is now, and the volume nodes in it
        // (the plan's graph for the first increment).
        std::vector<std::int32_t> simplices, representative;
        std::vector<double> barycentric;
        if (j == 1) {
            representative = plan_representatives(plan);
        } else {
            for (std::size_t b = 0; b < plan.boundary_nodes.size(); ++b)
                std::copy_n(previous.begin() + b * dim, dim, current.begin() + plan.boundary_nodes[b] * dim);
            LocatedGraph lg = build_located_graph(dim, current, plan.boundary_nodes, volume);
            const DelaunayGraph& g = lg.graph;
            representative.resize(g.num_vertices());
            std::vector<NodeId> vertex_node(g.num_vertices());
            for (std::size_t v = 0; v < representative.size(); ++v) {
                representative[v] = g.vertex_nodes[g.vertex_offsets[v]];
                vertex_node[v] = plan.boundary_nodes[representative[v]];
            }
            barycentric =
                detail::barycentric_coordinates(dim, current, vertex_node, g.simplices, volume, lg.location.simplex);
            simplices = std::move(lg.graph.simplices);
            volume_simplex = std::move(lg.location.simplex);
        }
        const std::span<const std::int32_t> graph = j == 1 ? std::span<const std::int32_t>(plan.simplices) : simplices;
        const std::vector<double> to = vertex_positions(dim, representative, next);
        std::vector<double> disp = vertex_positions(dim, representative, previous);
        const std::int64_t bad = count_invalid_moved_simplices(dim, graph, disp, to);
        if (bad > 0) return {false, bad, static_cast<std::int64_t>(graph.size() / (dim + 1)), j};
        for (std::size_t i = 0; i < disp.size(); ++i) disp[i] = to[i] - disp[i];
        advance_volume(dim, graph, volume_simplex,
                       j == 1 ? std::span<const double>(plan.node_barycentric) : barycentric, disp, volume, current);
        previous = next;
    }
    return {true, 0, 0, k};
}

void check_sizes(const DgmPlan& plan, std::span<const double> points, const BoundaryMotion& motion,
                 std::span<double> out) {
    check_step_arrays("DGM", plan.num_points(), plan.dim, plan.boundary_nodes, points, motion, out);
}

}  // namespace

DgmStepReport deform_dgm(const DgmPlan& plan, std::span<const double> points, const BoundaryMotion& motion,
                         std::span<double> out, const DgmOptions& options) {
    detail::check_dgm_options(options);
    check_sizes(plan, points, motion, out);
    const int dim = plan.dim;
    DgmStepReport report;
    report.conflicting_shared_vertices = conflicting_shared_vertices(plan, motion);

    // One step: the graph moved by the whole motion.
    const std::vector<std::int32_t> source = graph_motion_source(plan);
    const std::vector<std::int32_t> representative = plan_representatives(plan);
    const std::vector<double> from = vertex_positions(dim, representative, graph_positions(plan, points, motion, source, 0.0));
    const std::vector<double> to = vertex_positions(dim, representative, graph_positions(plan, points, motion, source, 1.0));
    // A non-finite graph vertex (a NaN in the points given) is an invalid graph; the
    // orientation predicates must not see it.
    const auto non_finite = std::count_if(from.begin(), from.end(), [](double v) { return !std::isfinite(v); }) +
                            std::count_if(to.begin(), to.end(), [](double v) { return !std::isfinite(v); });
    if (non_finite > 0)
        throw InvalidResultError("DGM: " + std::to_string(non_finite) +
                                     " coordinates of the Delaunay graph's vertices, before or after the motion, are not "
                                     "finite (check the points given to the step)",
                                 non_finite);
    report.invalid_simplices = count_invalid_moved_simplices(dim, plan.simplices, from, to);
    const auto num_simplices = static_cast<std::int64_t>(plan.simplices.size() / (dim + 1));
    if (report.invalid_simplices == 0) {
        std::vector<double> disp(to.size());
        for (std::size_t i = 0; i < disp.size(); ++i) disp[i] = to[i] - from[i];
        write_one_step(plan, points, motion, disp, out);
        return report;
    }
    const std::string found = "DGM: the moved Delaunay graph has " + std::to_string(report.invalid_simplices) +
                              " invalid (flat or inverted) simplices of " + std::to_string(num_simplices);
    if (options.on_invalid == DgmOptions::OnInvalidGraph::fail || options.max_substeps < 2)
        throw InvalidResultError(found + "; mapping through it would fold the mesh (sub-steps were not allowed)",
                                 report.invalid_simplices);

    std::vector<NodeId> volume;
    volume.reserve(static_cast<std::size_t>(plan.num_volume_nodes()));
    for (std::int64_t n = 0; n < plan.num_points(); ++n)
        if (plan.node_simplex[n] >= 0) volume.push_back(static_cast<NodeId>(n));
    std::vector<double> current;
    SubstepResult last;
    for (int k = 2;; k = std::min(2 * k, options.max_substeps)) {
        last = map_in_increments(plan, points, motion, source, volume, k, current);
        if (last.valid) {
            report.substeps = k;
            break;
        }
        if (k >= options.max_substeps)
            throw InvalidResultError(found + "; with " + std::to_string(k) + " sub-steps (the most allowed), " +
                                         std::to_string(last.invalid_simplices) + " of " +
                                         std::to_string(last.num_simplices) + " are still invalid in increment " +
                                         std::to_string(last.increment),
                                     last.invalid_simplices);
    }
    // Boundary nodes by their own motion, volume nodes from the last increment.
    parallel_for(plan.num_points(), [&](std::int64_t n) {
        const auto x = points.subspan(static_cast<std::size_t>(n) * dim, dim);
        const auto y = out.subspan(static_cast<std::size_t>(n) * dim, dim);
        const std::int32_t s = plan.node_simplex[n];
        if (s < 0 && plan.boundary_moving[-1 - s]) apply_motion(motion[-1 - s], x, y);
        else if (s < 0) std::copy(x.begin(), x.end(), y.begin());
        else std::copy_n(current.begin() + n * dim, dim, y.begin());
    });
    return report;
}

}  // namespace dgwarp
