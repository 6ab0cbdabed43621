#pragma once
// One interface for every deformation method: prepare once per mesh and
// boundary classification, deform every step. Tools and benchmarks choose a
// method by value and treat them all alike:
//
//   Plan plan = prepare(Method::dg_idw, dim, points, boundary, options);
//   StepReport r = deform(plan, points, motion, out, options);
//
// Both take an optional last argument, a ProgressFn (core/progress.hpp) that
// gets the fraction done of long calls.
//
// Methods (METHODS.md): DG-IDW (the paper's), DGM (Delaunay graph mapping),
// IDW (global inverse distance weighting), RBF (radial basis functions), and
// DG-harmonic (ours: the robust two-level method, docs/dg-harmonic.md).
// Conventions as everywhere: points num_points × dim row-major, 0-based ids,
// motions one NodeMotion per boundary node in BoundarySet order.
#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <span>
#include <string_view>
#include <variant>
#include <vector>

#include "dgwarp/core/warning.hpp"
#include "dgwarp/methods/dg_harmonic.hpp"
#include "dgwarp/methods/dg_harmonic_guard.hpp"
#include "dgwarp/methods/dg_idw.hpp"
#include "dgwarp/methods/dgm.hpp"
#include "dgwarp/methods/idw.hpp"
#include "dgwarp/methods/laplacian.hpp"
#include "dgwarp/methods/rbf.hpp"
#include "dgwarp/motion/node_motion.hpp"

namespace dgwarp {

enum class Method { dg_idw, dgm, idw, rbf, dg_harmonic, laplacian };

/// All methods, in the order tools list them.
inline constexpr Method all_methods[] = {Method::dg_idw, Method::dgm,         Method::idw,
                                         Method::rbf,    Method::dg_harmonic, Method::laplacian};

/// Whether `m` solves on the mesh's cells (prepare needs them): laplacian
/// only; the others work on points and a boundary set (DG-harmonic uses the
/// cells when given, for its guard: dg_harmonic_guard.hpp).
constexpr bool method_needs_cells(Method m) { return m == Method::laplacian; }

/// "dg-idw", "dgm", "idw", "rbf", "dg-harmonic", "laplacian".
std::string_view method_name(Method m);

/// The method called `name` (as method_name prints it), or nullopt.
std::optional<Method> method_from_name(std::string_view name);

/// Options of every method, each in its own plain struct with defaults.
struct MethodOptions {
    DgIdwOptions dg_idw;  // acts at prepare time (the plan keeps it)
    DgmOptions dgm;
    IdwOptions idw;
    RbfOptions rbf;  // acts at prepare time (the plan keeps it)
    DgHarmonicOptions dg_harmonic;  // acts at prepare time (the plan keeps it)
    LaplacianOptions laplacian;     // acts at prepare time (the plan keeps it)
};

/// A prepared plan of any method.
using Plan = std::variant<DgIdwPlan, DgmPlan, IdwPlan, RbfPlan, DgHarmonicPlan, LaplacianPlan>;

/// What one step did, whatever the method (fields a method does not use keep their defaults).
struct StepReport {
    std::int64_t conflicting_shared_vertices = 0;  // DG-IDW, DGM, RBF: shared graph vertices (RBF centres) with differing motions
    int substeps = 1;                               // DGM, laplacian (and DG-harmonic's result when laplacian's was kept): increments used (1 = one step)
    std::int64_t invalid_graph_simplices = 0;       // DGM: invalid simplices of the graph moved in one step
    std::int64_t rbf_centres = 0;                   // RBF: centres used (all boundary nodes without greedy reduction)
    double rbf_boundary_error = 0;                  // RBF: max |s(x_b) - d_b| over the boundary nodes (mesh units)
    DgHarmonicGuardReport guard;                    // DG-harmonic: what its guard measured and whether laplacian solved the step again
};

/// Builds the plan of `method` for the original `points` and `boundary`.
/// Throws as the method's own prepare does (MeshError for a bad boundary set
/// or degenerate geometry, Error for bad options). Method::laplacian solves
/// on the mesh's cells: it needs the overload below (here it throws Error).
/// `progress` gets the fraction done, ending at 1: per block of located volume
/// nodes (DG-IDW, DGM), per phase of the factorisation (RBF); IDW has nothing
/// to prepare.
Plan prepare(Method method, int dim, std::span<const double> points, const BoundarySet& boundary,
             const MethodOptions& options = {}, const ProgressFn& progress = {});

/// The same, with the mesh's `cells` (as Mesh::cells), which Method::laplacian
/// solves on and Method::dg_harmonic's guard measures its steps with (empty:
/// no guard): the one call for tools that run every method.
Plan prepare(Method method, int dim, std::span<const double> points, const ElementList& cells,
             const BoundarySet& boundary, const MethodOptions& options = {}, const ProgressFn& progress = {});

/// One step: writes the new coordinates of every node to `out`
/// (num_points × dim; may alias `points`). Throws as the method's deform does
/// (MeshError on size mismatch, InvalidResultError when the method cannot
/// produce a valid result and was told to fail). Never returns a non-finite
/// coordinate: InvalidResultError naming the first such node and the cause
/// (a motion too large for double arithmetic, or options that make the
/// weights overflow), `out` then unspecified.
/// `progress` gets the fraction done, ending at 1: per block of volume nodes
/// (IDW, DG-IDW, DG-harmonic's pass after its coarse solve, RBF's evaluation
/// after its solve), per increment (laplacian); DGM reports only the end.
StepReport deform(const Plan& plan, std::span<const double> points, const BoundaryMotion& motion,
                  std::span<double> out, const MethodOptions& options = {}, const ProgressFn& progress = {});

/// The method a plan belongs to.
Method plan_method(const Plan& plan);

/// The core of a graph method's plan (DG-IDW, DGM, DG-harmonic: plan_core.hpp), or null.
const GraphPlanCore* graph_plan_core(const Plan& plan);

/// Bytes held by a plan's arrays.
std::size_t plan_memory_bytes(const Plan& plan);

/// What a plan holds and how long building it took, whatever the method
/// (counts a method does not have stay 0).
struct PlanSummary {
    /// DG-IDW, DGM: simplices of the Delaunay graph of the boundary nodes;
    /// DG-harmonic: of its coarse graph. nullopt for a DG-IDW plan loaded from
    /// a file (the plan keeps only the simplices that hold a volume node).
    std::optional<std::int64_t> graph_simplices = 0;
    /// DG-IDW, DGM, DG-harmonic: the graph simplices holding at least one
    /// volume node (what a DG-IDW plan keeps).
    std::int64_t graph_simplices_used = 0;
    std::int64_t outside_hull = 0;      // DG-IDW, DGM: volume nodes outside the graph's hull
    std::int64_t shared_vertices = 0;   // DG-IDW, DGM, DG-harmonic: graph vertices standing for several boundary nodes
    std::int64_t coarse_points = 0;     // DG-harmonic: volume nodes on the coarse level
    std::int64_t floored_weights = 0;   // DG-harmonic: coarse edge weights raised after a zero pivot (0 normally)
    /// Prepare phases in order, e.g. {"graph", 0.01}, {"locate", 0.02}; empty for a loaded plan.
    std::vector<std::pair<std::string, double>> phase_seconds;
};
PlanSummary plan_summary(const Plan& plan);

/// The warnings about `method`'s plan summed up in `s`: the volume nodes
/// outside the graph's hull (DG-IDW and DGM extrapolate there), if any.
std::vector<Warning> plan_warnings(Method method, const PlanSummary& s);

}  // namespace dgwarp
