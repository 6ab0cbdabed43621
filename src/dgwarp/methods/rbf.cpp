// prepare_rbf, solve_rbf, deform_rbf: the RBF method's steps (rbf.hpp).
#include "dgwarp/methods/method_inputs.hpp"
#include "dgwarp/methods/rbf.hpp"

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <string>

#include "dgwarp/core/error.hpp"
#include "dgwarp/core/parallel_for.hpp"
#include "dgwarp/core/stopwatch.hpp"
#include "dgwarp/graph/coincident_points.hpp"
#include "dgwarp/methods/boundary_set_tools.hpp"
#include "dgwarp/methods/graph_vertex_motion.hpp"
#include "dgwarp/methods/rbf_centre_index.hpp"
#include "dgwarp/methods/rbf_internal.hpp"

namespace dgwarp {

namespace {

std::string gib(std::size_t bytes) {
    char text[32];
    std::snprintf(text, sizeof text, "%.2f GiB", static_cast<double>(bytes) / (1024.0 * 1024.0 * 1024.0));
    return text;
}

// Half the physical memory (POSIX sysconf); 8 GiB when it cannot be read.
std::size_t default_max_dense_bytes() {
    const long pages = sysconf(_SC_PHYS_PAGES), page = sysconf(_SC_PAGE_SIZE);
    if (pages <= 0 || page <= 0) return std::size_t{8} << 30;
    return static_cast<std::size_t>(pages) / 2 * static_cast<std::size_t>(page);
}

void check_options(const RbfOptions& options) {
    if (!std::isfinite(options.support_radius) || options.support_radius < 0)
        throw Error("RBF: support_radius must be finite and >= 0 (0 = global), got " +
                    std::to_string(options.support_radius));
    if (!std::isfinite(options.greedy_tolerance) || options.greedy_tolerance < 0)
        throw Error("RBF: greedy_tolerance must be finite and >= 0 (0 = all centres), got " +
                    std::to_string(options.greedy_tolerance));
}

// Centre of the bounding box of the boundary nodes.
std::array<double, 3> box_centre(int dim, std::span<const double> boundary_points) {
    std::array<double, 3> lo{}, hi{};
    lo.fill(std::numeric_limits<double>::infinity());
    hi.fill(-std::numeric_limits<double>::infinity());
    for (std::size_t i = 0; i < boundary_points.size(); ++i) {
        const auto k = i % static_cast<std::size_t>(dim);
        lo[k] = std::min(lo[k], boundary_points[i]);
        hi[k] = std::max(hi[k], boundary_points[i]);
    }
    std::array<double, 3> c{};
    for (int k = 0; k < dim; ++k) c[k] = 0.5 * (lo[k] + hi[k]);
    return c;
}

// The centres of `plan` (boundary_nodes and boundary_moving set): one per
// distinct position, taking the motion of its first moving boundary node.
void make_centres(std::span<const double> points, RbfPlan& plan) {
    const int dim = plan.dim;
    const CoincidentGroups groups = group_coincident_points(dim, points, plan.boundary_nodes);
    plan.centre_points.reserve(groups.size() * static_cast<std::size_t>(dim));
    plan.centre_source.reserve(groups.size());
    for (std::size_t g = 0; g < groups.size(); ++g) {
        const auto first = groups.members.begin() + groups.offsets[g];
        const auto last = groups.members.begin() + groups.offsets[g + 1];
        const auto mover = std::find_if(first, last, [&](std::int32_t b) { return plan.boundary_moving[b] != 0; });
        plan.centre_source.push_back(mover != last ? *mover : *first);
        const auto n = static_cast<std::size_t>(plan.boundary_nodes[static_cast<std::size_t>(*first)]);
        for (int d = 0; d < dim; ++d) plan.centre_points.push_back(points[n * dim + d]);
        if (last - first > 1) {
            plan.shared_members.insert(plan.shared_members.end(), first, last);
            plan.shared_offsets.push_back(static_cast<std::int32_t>(plan.shared_members.size()));
        }
    }
}

void check_sizes(const RbfPlan& plan, std::span<const double> points, const BoundaryMotion& motion,
                 std::span<double> out) {
    check_step_arrays("RBF", plan.num_points, plan.dim, plan.boundary_nodes, points, motion, out);
}

// max_b |s(x_b) - d_b| for the coefficients c.
double boundary_error(const RbfPlan& plan, const RbfCoefficients& c, std::span<const double> d) {
    std::vector<double> s(d.size());
    evaluate_rbf(plan, c, plan.centre_points, s);
    double worst = 0;
    for (std::size_t b = 0; b < plan.num_centres(); ++b) {
        double e2 = 0;
        for (int k = 0; k < plan.dim; ++k) e2 += (s[b * plan.dim + k] - d[b * plan.dim + k]) * (s[b * plan.dim + k] - d[b * plan.dim + k]);
        worst = std::max(worst, std::sqrt(e2));
    }
    return worst;
}

}  // namespace

void check_dense_bytes(std::size_t needed, std::size_t max_dense_bytes, const std::string& what) {
    if (needed <= max_dense_bytes) return;
    throw Error("RBF: " + what + " would need " + std::to_string(needed) + " bytes (" + gib(needed) +
                "), more than max_dense_bytes = " + std::to_string(max_dense_bytes) + " (" + gib(max_dense_bytes) +
                "); use greedy reduction (greedy_tolerance > 0) or a compact support (support_radius below the "
                "boundary's bounding-box diagonal, with the sparse solver)");
}

RbfPlan prepare_rbf(int dim, std::span<const double> points, const BoundarySet& boundary, const RbfOptions& options,
                    const ProgressFn& progress) {
    const std::size_t num_points = checked_point_count("RBF", dim, points);
    check_options(options);
    check_boundary_set(num_points, boundary);

    RbfPlan plan;
    plan.dim = dim;
    plan.num_points = static_cast<std::int64_t>(num_points);
    plan.boundary_nodes = boundary.nodes;
    plan.boundary_moving = boundary.moving;
    make_centres(points, plan);
    if (plan.num_centres() < static_cast<std::size_t>(dim + 1))
        throw MeshError("RBF needs at least " + std::to_string(dim + 1) + " boundary nodes at distinct positions in " +
                        std::to_string(dim) + "D, got " + std::to_string(plan.num_centres()));
    plan.diagonal = boundary_diagonal(dim, points, boundary, false);
    if (!(plan.diagonal > 0)) throw MeshError("RBF: all boundary nodes are at the same point");
    plan.shift = box_centre(dim, plan.centre_points);
    plan.radius = options.support_radius > 0 ? options.support_radius : plan.diagonal;
    plan.compact = plan.radius < plan.diagonal;
    plan.greedy_tolerance = options.greedy_tolerance;
    plan.max_dense_bytes = options.max_dense_bytes > 0 ? options.max_dense_bytes : default_max_dense_bytes();
    plan.dense = options.greedy_tolerance == 0 &&
                 (options.solver == RbfSolver::dense || (options.solver == RbfSolver::automatic && !plan.compact));

    const auto t0 = Clock::now();
    if (plan.compact || (options.greedy_tolerance == 0 && !plan.dense))
        plan.index = build_centre_index(dim, plan.centre_points);
    const double index_seconds = seconds_since(t0);
    if (options.greedy_tolerance == 0) {
        if (plan.dense) {
            const std::size_t nb = plan.num_centres();
            check_dense_bytes(nb * nb * sizeof(double) + nb * (2 * dim + 2) * sizeof(double), plan.max_dense_bytes,
                              "the dense " + std::to_string(nb) + " x " + std::to_string(nb) +
                                  " RBF system (factorised in place, plus P and M^-1 P)");
        }
        plan.factorization = factorize_rbf(plan, plan.stats, progress);
    }
    plan.stats.matrix_seconds += index_seconds;
    if (progress) progress(1.0);
    return plan;
}

std::vector<double> rbf_boundary_displacements(const RbfPlan& plan, const BoundaryMotion& motion) {
    if (motion.size() != plan.boundary_nodes.size())
        throw MeshError("RBF: the motion has " + std::to_string(motion.size()) + " entries but the plan has " +
                        std::to_string(plan.boundary_nodes.size()) + " boundary nodes");
    const int dim = plan.dim;
    std::vector<double> d(plan.centre_points.size(), 0.0);
    for (std::size_t c = 0; c < plan.num_centres(); ++c) {
        const auto b = static_cast<std::size_t>(plan.centre_source[c]);
        if (!plan.boundary_moving[b]) continue;
        const std::span<const double> x(plan.centre_points.data() + c * dim, dim);
        double y[3];
        apply_motion(motion[b], x, std::span<double>(y, dim));
        for (int k = 0; k < dim; ++k) d[c * dim + k] = y[k] - x[k];
    }
    return d;
}

RbfCoefficients solve_rbf(const RbfPlan& plan, const BoundaryMotion& motion) {
    const auto t0 = Clock::now();
    const std::vector<double> d = rbf_boundary_displacements(plan, motion);
    RbfCoefficients c;
    c.dim = plan.dim;
    if (plan.factorization) {
        solve_full(plan, d, c);
        c.report.centres = static_cast<std::int64_t>(c.centres.size());
        c.report.boundary_error = boundary_error(plan, c, d);
    } else {
        solve_greedy(plan, d, c);
    }
    c.report.solve_seconds = seconds_since(t0);
    return c;
}

RbfStepReport deform_rbf(const RbfPlan& plan, std::span<const double> points, const BoundaryMotion& motion,
                         std::span<double> out, const ProgressFn& progress) {
    check_sizes(plan, points, motion, out);
    if (progress) progress(0.0);
    const RbfCoefficients c = solve_rbf(plan, motion);
    // The solve's share of the step: the greedy loop rivals the evaluation,
    // the full system's triangular solves do not.
    const ProgressFn evaluate_progress = progress_part(progress, plan.factorization ? 0.1 : 0.5, 1.0);
    ProgressCounter moved(evaluate_progress, plan.num_volume_nodes());
    const auto t0 = Clock::now();
    move_volume_nodes(plan, c, points, out, moved);  // reads only volume nodes: `out` may alias `points`
    const int dim = plan.dim;
    parallel_for(static_cast<std::int64_t>(plan.boundary_nodes.size()), [&](std::int64_t b) {
        const auto n = static_cast<std::size_t>(plan.boundary_nodes[b]);
        const std::span<const double> x = points.subspan(n * dim, dim);
        const std::span<double> y = out.subspan(n * dim, dim);
        if (plan.boundary_moving[b]) apply_motion(motion[b], x, y);
        else std::copy(x.begin(), x.end(), y.begin());
    });
    moved.finish();
    RbfStepReport report = c.report;
    report.evaluate_seconds = seconds_since(t0);
    report.conflicting_shared_centres =
        count_conflicting_shared_vertices(plan.shared_offsets, plan.shared_members, plan.boundary_moving, motion);
    return report;
}

std::size_t plan_bytes(const RbfPlan& plan) {
    return plan.boundary_nodes.capacity() * sizeof(NodeId) + plan.boundary_moving.capacity() +
           plan.centre_points.capacity() * sizeof(double) +
           (plan.centre_source.capacity() + plan.shared_offsets.capacity() + plan.shared_members.capacity()) *
               sizeof(std::int32_t) +
           (plan.factorization ? factorization_bytes(*plan.factorization) : 0) +
           (plan.index ? index_bytes(*plan.index) : 0);
}

}  // namespace dgwarp
