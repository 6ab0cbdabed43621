#pragma once
// A job's plan: a method's, built for the job's inputs (job_inputs.hpp) or
// loaded from a plan file and checked to fit them, with the sliding markers'
// first pass; and what the reports say of it (docs/JSON.md).
//
//   PlanRequest r;
//   r.method = Method::dg_harmonic;
//   r.plan_file = "wing.plan";  // or "" to build it
//   measure_original_cells(in, [&] { plan = plan_job(in, r); });
//   for (const Warning& w : job_plan_warnings(plan)) print(w.text);
#include <cstdint>
#include <functional>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "dgwarp/core/progress.hpp"
#include "dgwarp/core/warning.hpp"
#include "dgwarp/job/job_inputs.hpp"
#include "dgwarp/methods/method.hpp"
#include "dgwarp/run/slide_pass.hpp"

namespace dgwarp {

/// How to get a job's plan.
struct PlanRequest {
    Method method = Method::dg_harmonic;
    /// The options asked for. A loaded plan's own replace those it keeps
    /// (options_with_plan); the others (the run's: DG-harmonic's guard) stay.
    MethodOptions options{};
    /// "" to build the plan; else a DG-IDW or DG-harmonic plan file.
    std::string plan_file{};
    /// `method` was asked for: a plan file of another method is refused
    /// (else the file's method runs).
    bool method_given = false;
    /// The options the caller set (method_option_table's names): with a
    /// plan file, one whose value differs from the plan's is refused rather
    /// than silently dropped.
    std::set<std::string> given{};
    /// Called with the method that runs as soon as it is known: before the
    /// work for a built plan; for a plan file, once it is read and its
    /// options checked (e.g. to refuse the options of another method); may throw.
    std::function<void(Method)> check_method{};
    /// The prepare, when not prepare_for_frames on this process (e.g. a plan
    /// spread over processes, of which it returns this process's own).
    std::function<Plan(const MethodOptions&)> prepare{};
};

/// A job's plan, and what its reports need of it.
struct JobPlan {
    Method method = Method::dg_harmonic;
    MethodOptions options;  // the plan's (a loaded plan's own)
    std::string plan_file;  // "" when built
    Plan plan;
    double prepare_seconds = 0;
    std::optional<SlidePass> slide;  // with sliding markers: their first pass (run/slide_pass.hpp)
    /// A plan spread over processes (its caller sets them): the volume nodes
    /// outside the graph's hull summed over the processes, and each process's
    /// prepare seconds; `plan` is then one process's own.
    std::optional<std::int64_t> outside_hull_over_processes;
    std::vector<double> process_prepare_seconds;
};

/// The plan `r` asks for: loaded from r.plan_file (load_plan: checked to
/// fit in.mesh and in.boundary; DG-harmonic's guard built again from the
/// mesh's cells, attach_frame_guard) or built (r.prepare, else
/// prepare_for_frames), and the sliding markers' first pass when the
/// boundary has any. `phase` (when given) is told what starts ("loading F",
/// "preparing dg-idw"), `progress` the prepare's fraction done. Throws UsageError naming the option
/// ("--length-scale: F was prepared with --length-scale auto; ...") when a
/// given option differs from a loaded plan's, or the file holds another
/// method's plan than an asked-for one; else as load_plan and prepare throw.
JobPlan plan_job(const JobInputs& in, const PlanRequest& r,
                 const std::function<void(const std::string&)>& phase = {}, const ProgressFn& progress = {});

/// plan_summary of the plan, with the nodes outside the hull of every process when spread.
PlanSummary job_plan_summary(const JobPlan& p);

/// plan_warnings of the plan (the volume nodes outside the graph's hull).
std::vector<Warning> job_plan_warnings(const JobPlan& p);

/// The reports' `plan` object (docs/JSON.md).
nlohmann::json plan_json(const JobPlan& p);

/// The reports' `boundary` object (docs/JSON.md).
nlohmann::json boundary_json(const JobInputs& in);

/// The nodes of each processor folder of a decomposed OpenFOAM case read
/// whole (in.extras.openfoam's processors' points, in in.mesh's numbering: a
/// 2D case's 2D nodes, sorted), when it has `processes` of them: a run
/// spread over as many processes gives each its processor's nodes (the
/// solver's decomposition). Empty otherwise.
std::vector<std::vector<NodeId>> processor_node_parts(const JobInputs& in, int processes);

}  // namespace dgwarp
