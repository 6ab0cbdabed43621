#include "dgwarp/methods/method.hpp"

#include "dgwarp/core/parallel_for.hpp"
#include "dgwarp/methods/dg_harmonic_guard.hpp"

#include <algorithm>

#include "dgwarp/core/error.hpp"
#include "dgwarp/core/stopwatch.hpp"
#include "dgwarp/methods/method_inputs.hpp"

namespace dgwarp {

namespace {
template <class... F>
struct overloaded : F... {
    using F::operator()...;
};
template <class... F>
overloaded(F...) -> overloaded<F...>;

// How many distinct graph simplices the nodes lie in (node_simplex: a
// simplex >= 0 per volume node, < 0 for a boundary node).
// Marked in a table of the simplices, not sorted (826k nodes: 48 -> 2 ms).
std::int64_t simplices_holding_a_node(const std::vector<std::int32_t>& node_simplex) {
    std::int32_t largest = -1;
    for (std::int32_t k : node_simplex) largest = std::max(largest, k);
    std::vector<std::uint8_t> held(static_cast<std::size_t>(largest + 1), 0);
    std::int64_t count = 0;
    for (std::int32_t k : node_simplex)
        if (k >= 0 && !held[static_cast<std::size_t>(k)]) {
            held[static_cast<std::size_t>(k)] = 1;
            ++count;
        }
    return count;
}
}  // namespace

std::string_view method_name(Method m) {
    switch (m) {
        case Method::dg_idw: return "dg-idw";
        case Method::dgm: return "dgm";
        case Method::idw: return "idw";
        case Method::rbf: return "rbf";
        case Method::dg_harmonic: return "dg-harmonic";
        case Method::laplacian: return "laplacian";
    }
    return "?";
}

std::optional<Method> method_from_name(std::string_view name) {
    for (Method m : all_methods)
        if (method_name(m) == name) return m;
    return std::nullopt;
}

Plan prepare(Method method, int dim, std::span<const double> points, const BoundarySet& boundary,
             const MethodOptions& options, const ProgressFn& progress) {
    if (method == Method::laplacian)
        throw Error("laplacian solves on the mesh's cells: call prepare with them (prepare(method, dim, points, "
                    "cells, boundary, options))");
    return prepare(method, dim, points, ElementList{}, boundary, options, progress);
}

Plan prepare(Method method, int dim, std::span<const double> points, const ElementList& cells,
             const BoundarySet& boundary, const MethodOptions& options, const ProgressFn& progress) {
    switch (method) {
        case Method::dg_idw: return prepare_dg_idw(dim, points, boundary, options.dg_idw, progress);
        case Method::dgm: return prepare_dgm(dim, points, boundary, options.dgm, progress);
        case Method::idw: {
            Plan plan = prepare_idw(dim, points, boundary, options.idw);
            if (progress) progress(1.0);
            return plan;
        }
        case Method::rbf: return prepare_rbf(dim, points, boundary, options.rbf, progress);
        case Method::dg_harmonic: {
            // The guard (the cells' copy, orientations, layout and the
            // original's measure) needs nothing of the plan. On two threads
            // it is built beside the plan, each on one thread (run_concurrently):
            // on the 865k sphere 2.3 s of prepare became 1.5-1.7 s. With more
            // threads each is built in turn on all of them (their loops are
            // parallel), as on one.
            DgHarmonicPlan plan;
            std::shared_ptr<const DgHarmonicGuard> guard;
            double guard_seconds = 0;
            const auto make_plan = [&] { plan = prepare_dg_harmonic(dim, points, boundary, options.dg_harmonic, progress); };
            const auto make_guard = [&] {
                if (cells.empty()) return;
                Stopwatch sw;
                guard = make_dg_harmonic_guard(dim, points, cells, boundary,
                                               guard_laplacian_options(options.laplacian, options.dg_harmonic));
                guard_seconds = sw.lap();
            };
            if (num_threads() == 2 && !cells.empty()) {
                run_concurrently(make_plan, make_guard);
            } else {
                make_plan();
                make_guard();
            }
            plan.guard = std::move(guard);
            plan.stats.guard_seconds = guard_seconds;
            return plan;
        }
        case Method::laplacian: {
            Plan plan = prepare_laplacian(dim, points, cells, boundary, options.laplacian);
            if (progress) progress(1.0);
            return plan;
        }
    }
    return {};
}

namespace {
StepReport deform_unchecked(const Plan& plan, std::span<const double> points, const BoundaryMotion& motion,
                            std::span<double> out, const MethodOptions& options, const ProgressFn& progress) {
    // DGM: one pass over the nodes, milliseconds; only the end is reported.
    const auto done = [&](StepReport r) {
        if (progress) progress(1.0);
        return r;
    };
    return std::visit(overloaded{[&](const DgIdwPlan& p) {
                                     StepReport r;
                                     r.conflicting_shared_vertices =
                                         deform_dg_idw(p, points, motion, out, progress)
                                             .conflicting_shared_vertices;
                                     return r;
                                 },
                                 [&](const DgmPlan& p) {
                                     const DgmStepReport d = deform_dgm(p, points, motion, out, options.dgm);
                                     StepReport r;
                                     r.conflicting_shared_vertices = d.conflicting_shared_vertices;
                                     r.substeps = d.substeps;
                                     r.invalid_graph_simplices = d.invalid_simplices;
                                     return done(r);
                                 },
                                 [&](const IdwPlan& p) {
                                     deform_idw(p, points, motion, out, options.idw, progress);
                                     return StepReport{};
                                 },
                                 [&](const RbfPlan& p) {
                                     const RbfStepReport rbf = deform_rbf(p, points, motion, out, progress);
                                     StepReport r;
                                     r.rbf_centres = rbf.centres;
                                     r.rbf_boundary_error = rbf.boundary_error;
                                     r.conflicting_shared_vertices = rbf.conflicting_shared_centres;
                                     return r;
                                 },
                                 [&](const DgHarmonicPlan& p) {
                                     StepReport r;
                                     r.guard = deform_dg_harmonic_guarded(p, points, motion, out,
                                                                          options.dg_harmonic.redo_below, progress);
                                     r.conflicting_shared_vertices = r.guard.conflicting_shared_vertices;
                                     if (r.guard.kept_redo) r.substeps = r.guard.increments;
                                     return r;
                                 },
                                 [&](const LaplacianPlan& p) {
                                     StepReport r;
                                     r.substeps = deform_laplacian(p, points, motion, out, progress).increments;
                                     return r;
                                 }},
                      plan);
}
}  // namespace

StepReport deform(const Plan& plan, std::span<const double> points, const BoundaryMotion& motion,
                  std::span<double> out, const MethodOptions& options, const ProgressFn& progress) {
    const StepReport report = deform_unchecked(plan, points, motion, out, options, progress);
    // Where the coordinates leave the library: every caller (the CLI, Python,
    // a solver) gets an error instead of a NaN, even at a node in no cell.
    const int dim = std::visit([](const auto& p) { return p.dim; }, plan);
    check_step_result(method_name(plan_method(plan)), dim, out, motion);
    return report;
}

Method plan_method(const Plan& plan) {
    return std::visit(overloaded{[](const DgIdwPlan&) { return Method::dg_idw; },
                                 [](const DgmPlan&) { return Method::dgm; },
                                 [](const IdwPlan&) { return Method::idw; },
                                 [](const RbfPlan&) { return Method::rbf; },
                                 [](const DgHarmonicPlan&) { return Method::dg_harmonic; },
                                 [](const LaplacianPlan&) { return Method::laplacian; }},
                      plan);
}

std::size_t plan_memory_bytes(const Plan& plan) {
    return std::visit([](const auto& p) { return plan_bytes(p); }, plan);
}

PlanSummary plan_summary(const Plan& plan) {
    PlanSummary s;
    std::visit(overloaded{[&](const DgIdwPlan& p) {
                              // The plan keeps only the simplices that hold a volume node;
                              // the graph's count is known to the plan prepare built.
                              if (p.stats.graph_simplex_count > 0) s.graph_simplices = p.stats.graph_simplex_count;
                              else s.graph_simplices.reset();
                              s.graph_simplices_used = static_cast<std::int64_t>(p.simplex_motion.size()) / (p.dim + 1);
                              s.outside_hull = p.stats.outside_count;
                              s.shared_vertices = p.stats.shared_vertex_count;
                              if (p.stats.graph_seconds > 0 || p.stats.locate_seconds > 0)
                                  s.phase_seconds = {{"graph", p.stats.graph_seconds},
                                                     {"locate", p.stats.locate_seconds},
                                                     {"weights", p.stats.weights_seconds}};
                          },
                          [&](const DgmPlan& p) {
                              s.graph_simplices = static_cast<std::int64_t>(p.simplices.size()) / (p.dim + 1);
                              s.graph_simplices_used = simplices_holding_a_node(p.node_simplex);
                              s.outside_hull = p.stats.outside_count;
                              s.shared_vertices = p.stats.shared_vertex_count;
                              s.phase_seconds = {{"graph", p.stats.graph_seconds},
                                                 {"locate", p.stats.locate_seconds},
                                                 {"barycentric", p.stats.barycentric_seconds}};
                          },
                          [&](const IdwPlan&) {},
                          [&](const RbfPlan& p) {
                              s.phase_seconds = {{"matrix", p.stats.matrix_seconds},
                                                 {"factorise", p.stats.factor_seconds}};
                          },
                          [&](const DgHarmonicPlan& p) {
                              s.graph_simplices = static_cast<std::int64_t>(p.simplices.size()) / (p.dim + 1);
                              s.graph_simplices_used = simplices_holding_a_node(p.node_simplex);
                              s.outside_hull = p.stats.outside_count;
                              s.shared_vertices = p.stats.shared_vertex_count;
                              s.coarse_points = p.stats.coarse_interior;
                              s.floored_weights = p.stats.floored_weights;
                              if (p.stats.graph_seconds > 0 || p.stats.locate_seconds > 0)
                                  s.phase_seconds = {{"coarse points", p.stats.select_seconds},
                                                     {"graph", p.stats.graph_seconds},
                                                     {"locate", p.stats.locate_seconds},
                                                     {"factorise", p.stats.factor_seconds}};
                              if (p.guard) s.phase_seconds.emplace_back("guard", p.stats.guard_seconds);
                          },
                          [&](const LaplacianPlan&) {}},
               plan);
    return s;
}

const GraphPlanCore* graph_plan_core(const Plan& plan) {
    if (const auto* p = std::get_if<DgIdwPlan>(&plan)) return p;
    if (const auto* p = std::get_if<DgmPlan>(&plan)) return p;
    if (const auto* p = std::get_if<DgHarmonicPlan>(&plan)) return p;
    return nullptr;
}

std::vector<Warning> plan_warnings(Method method, const PlanSummary& s) {
    if (s.outside_hull == 0) return {};
    return {{WarningCode::outside_hull,
             std::to_string(s.outside_hull) + " volume node" + (s.outside_hull == 1 ? " is" : "s are") +
                 " outside the Delaunay graph's hull (the convex hull of the boundary nodes); " +
                 std::string(method_name(method)) +
                 " extrapolates the motion of the nearest hull simplex there. If the domain has an outer boundary "
                 "(far field, walls), it should be a marker of the mesh",
             "", s.outside_hull}};
}

}  // namespace dgwarp
