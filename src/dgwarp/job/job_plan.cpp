#include "dgwarp/job/job_plan.hpp"

#include <algorithm>

#include "dgwarp/core/error.hpp"
#include "dgwarp/core/stopwatch.hpp"
#include "dgwarp/methods/option_table.hpp"
#include "dgwarp/plan/plan_file.hpp"
#include "dgwarp/run/run_deformation.hpp"

namespace dgwarp {

namespace {

nlohmann::json cyclic_pairs_json(const std::vector<std::pair<std::string, std::string>>& pairs) {
    nlohmann::json out = nlohmann::json::array();
    for (const auto& [a, b] : pairs) out.push_back({a, b});
    return out;
}

// A loaded plan fixes its method's options: one given that differs from
// the plan's is a mistake, not silently dropped.
void refuse_conflicts(const PlanRequest& r, Method planned, const MethodOptions& in_plan) {
    for (const MethodOption& row : method_option_table) {
        if (row.method != planned || !row.kept_by_plan || !r.given.count(std::string(row.name))) continue;
        const std::string asked = option_text(row, r.options), kept = option_text(row, in_plan);
        if (asked == kept) continue;
        const std::string flag = "--" + std::string(row.name);
        throw UsageError(flag + ": " + r.plan_file + " was prepared with " + flag + " " + kept +
                         "; prepare it again with the option, or drop it");
    }
}

}  // namespace

JobPlan plan_job(const JobInputs& in, const PlanRequest& r, const std::function<void(const std::string&)>& phase,
                 const ProgressFn& progress) {
    const auto tell = [&](const std::string& what) {
        if (phase) phase(what);
    };
    JobPlan p;
    p.method = r.method;
    p.options = r.options;
    p.plan_file = r.plan_file;
    Stopwatch sw;
    if (!r.plan_file.empty()) {
        tell("loading " + r.plan_file);
        Plan loaded = load_plan(r.plan_file, in.mesh.points, in.boundary.boundary);
        const Method planned = plan_method(loaded);
        if (r.method_given && planned != r.method)
            throw UsageError("--plan: " + r.plan_file + " is a " + std::string(method_name(planned)) +
                             " plan; it cannot be used with --method " + std::string(method_name(r.method)));
        p.method = planned;
        // The plan's options are the ones used. The guard acts at step time:
        // the run's value, and the mesh's cells it measures.
        const MethodOptions in_plan = options_with_plan(loaded, r.options);
        refuse_conflicts(r, planned, in_plan);
        if (r.check_method) r.check_method(planned);
        p.options = in_plan;
        // A plan file keeps the plan's arrays, not the guard: built again from the mesh's cells.
        attach_frame_guard(loaded, in.mesh, in.boundary.boundary, p.options);
        p.plan = std::move(loaded);
    } else {
        if (r.check_method) r.check_method(r.method);
        tell("preparing " + std::string(method_name(r.method)));
        p.plan = r.prepare ? r.prepare(p.options)
                           : prepare_for_frames(r.method, in.mesh, in.boundary.boundary, p.options, progress);
    }
    if (!in.boundary.slides.empty()) p.slide = prepare_slide_pass(in.mesh, in.boundary, p.options);
    p.prepare_seconds = sw.lap();
    return p;
}

PlanSummary job_plan_summary(const JobPlan& p) {
    PlanSummary s = plan_summary(p.plan);
    if (p.outside_hull_over_processes) s.outside_hull = *p.outside_hull_over_processes;
    return s;
}

std::vector<Warning> job_plan_warnings(const JobPlan& p) { return plan_warnings(p.method, job_plan_summary(p)); }

nlohmann::json plan_json(const JobPlan& p) {
    const PlanSummary s = job_plan_summary(p);
    nlohmann::json phases = nlohmann::json::object();
    for (const auto& [name, seconds] : s.phase_seconds) phases[name] = seconds;
    const auto* dg_idw = std::get_if<DgIdwPlan>(&p.plan);
    nlohmann::json j = {
        {"method", method_name(p.method)},
        {"file", p.plan_file.empty() ? nlohmann::json(nullptr) : nlohmann::json(p.plan_file)},
        {"dg_idw_weights", dg_idw ? nlohmann::json(weighting_name(dg_idw->options.weighting)) : nlohmann::json(nullptr)},
        {"graph_simplices", s.graph_simplices ? nlohmann::json(*s.graph_simplices) : nlohmann::json(nullptr)},
        {"graph_simplices_used", s.graph_simplices_used},
        {"outside_hull", s.outside_hull},
        {"shared_graph_vertices", s.shared_vertices},
        {"coarse_points", s.coarse_points},
        {"floored_weights", s.floored_weights},
        {"bytes", plan_memory_bytes(p.plan)},
        {"seconds", p.prepare_seconds},
        {"phase_seconds", phases}};
    // Spread over processes: every process's prepare time (the counts above are one process's plan's).
    if (!p.process_prepare_seconds.empty()) j["process_seconds"] = p.process_prepare_seconds;
    return j;
}

nlohmann::json boundary_json(const JobInputs& in) {
    const auto& b = in.boundary.boundary;
    return {{"nodes", b.nodes.size()},
            {"moving_nodes", moving_count(b)},
            {"moving_markers", in.boundary.moving_markers},
            {"static_markers", in.boundary.static_markers},
            {"sliding_markers", in.boundary.sliding_markers},
            {"sliding_nodes", in.boundary.slides.size()},
            {"sliding_by_type", in.sliding_by_type},
            {"cyclic_markers", in.boundary.cyclic_markers},
            {"cyclic_by_type", cyclic_pairs_json(in.coupled_by_type)},
            {"planar", in.planar ? nlohmann::json{{"plane_markers", in.planar->plane_markers},
                                                  {"nodes", in.mesh.num_points()},
                                                  {"cells", in.mesh.cells.size()},
                                                  {"normal", in.planar->normal},
                                                  {"thickness", in.planar->thickness}}
                                 : nlohmann::json(nullptr)}};
}

std::vector<std::vector<NodeId>> processor_node_parts(const JobInputs& in, int processes) {
    std::vector<std::vector<NodeId>> parts;
    if (!in.extras.openfoam || in.extras.openfoam->processors.size() != static_cast<std::size_t>(processes))
        return parts;
    for (const OpenFoamProcessor& processor : in.extras.openfoam->processors) {
        parts.push_back(processor.points);
        if (!in.planar) continue;
        // A 2D case: the 2D nodes of the processor's points.
        std::vector<NodeId>& part = parts.back();
        for (NodeId& v : part) v = in.planar->node_2d[static_cast<std::size_t>(v)];
        std::sort(part.begin(), part.end());
        part.erase(std::unique(part.begin(), part.end()), part.end());
    }
    return parts;
}

}  // namespace dgwarp
