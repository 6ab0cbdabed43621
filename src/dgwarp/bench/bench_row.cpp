#include "dgwarp/bench/bench_row.hpp"

#include "dgwarp/core/error.hpp"
#include "dgwarp/core/stopwatch.hpp"
#include "dgwarp/motion/resolve_motion.hpp"
#include "dgwarp/repair/untangle.hpp"

namespace dgwarp {

std::string bench_skip_reason(Method method, const BenchLimits& limits, std::size_t nodes, std::size_t boundary,
                              int dim) {
    const double nb = double(boundary), nv = double(nodes - boundary);
    if (method == Method::rbf && nb > limits.rbf_max_boundary)
        return "skipped: dense " + std::to_string(boundary) + "² system (" + std::to_string(int(nb * nb * 8 / 1e9)) +
               " GB, O(N_b³) solve); the paper did not run it either";
    if (method == Method::rbf && dim == 3 && limits.quick) return "skipped: --quick (dense 3D solve takes minutes)";
    if (method == Method::idw && nv * nb > limits.idw_max_work)
        return "skipped: N_v × N_b = " + std::to_string(static_cast<long long>(nv * nb)) + " (too long for one run)";
    if (method == Method::laplacian && dim == 3 && limits.quick)
        return "skipped: --quick (a 3D sparse factorisation per increment takes minutes)";
    if (method == Method::laplacian && double(nodes) > limits.laplacian_max_nodes)
        return "skipped: " + std::to_string(nodes) + " nodes (a 3D sparse factorisation per increment)";
    return "";
}

namespace {

/// A method, or a variant of one, as the bench runs it.
struct Variant {
    Method method;
    std::string label;
    MethodOptions options;
    bool untangle = false;  // repair inverted cells after the step (its time counts in the step)
};

std::vector<Variant> bench_variants() {
    std::vector<Variant> variants;
    for (Method m : all_methods) variants.push_back({m, std::string(method_name(m)), {}});
    variants.push_back({Method::dg_idw, "dg-idw L=auto", {}});
    variants.back().options.dg_idw.length_scale = 0;
    variants.push_back({Method::dg_idw, "dg-idw continuous", {}});
    variants.back().options.dg_idw.weighting = DgIdwWeighting::continuous;
    variants.push_back({Method::dg_idw, "dg-idw + untangle", {}, true});
    return variants;
}

}  // namespace

BenchRow measure_motion(const std::string& name, int size, const Mesh& mesh, const CaseMotion& cm,
                        const BenchLimits& limits, const BenchObserver& observer) {
    BenchRow row;
    row.case_name = name;
    row.size = size;
    row.motion = cm.name;
    row.motion_description = cm.description;
    row.nodes = mesh.num_points();
    row.cells = mesh.cells.size();
    row.paper = paper_entry(name, size, cm.name);
    const ResolvedBoundary b = resolve_boundary(mesh, cm.spec);
    const BoundaryMotion motion = resolve_frame(mesh, cm.spec, b, 0).motion;
    row.boundary_nodes = b.boundary.nodes.size();
    row.moving_nodes = static_cast<std::size_t>(moving_count(b.boundary));
    const std::vector<std::int8_t> orientation = cell_orientations(mesh);
    const std::vector<double> original = cell_qualities(mesh, orientation);
    row.original = summarize_quality(original);
    const auto progress = [&](const std::string& what) {
        return observer.progress ? observer.progress(what) : ProgressFn{};
    };
    Mesh deformed = mesh;
    for (const Variant& v : bench_variants()) {
        const Method method = v.method;
        MethodResult r;
        r.method = method;
        r.label = v.label;
        const std::string skip = bench_skip_reason(method, limits, mesh.num_points(), row.boundary_nodes, mesh.dim);
        if (!skip.empty()) {
            r.status = skip;
            row.methods.push_back(r);
            continue;
        }
        const std::string what = "bench: " + name + " " + std::to_string(size) + " " + cm.name + " " + v.label;
        if (observer.started) observer.started(what);
        try {
            Stopwatch sw;
            const Plan plan =
                prepare(method, mesh.dim, mesh.points, mesh.cells, b.boundary, v.options, progress(what + ": preparing"));
            r.prepare_seconds = sw.lap();
            const StepReport step =
                deform(plan, mesh.points, motion, deformed.points, v.options, progress(what + ": deforming"));
            if (v.untangle) untangle(mesh.dim, mesh.cells, orientation, b.boundary.nodes, deformed.points);
            r.step_seconds = sw.lap();
            const std::vector<double> q = cell_qualities(deformed, orientation);
            r.quality = summarize_quality(q);
            r.ran = true;
            if (step.substeps > 1 && method == Method::dgm)
                r.status = "ok (" + std::to_string(step.substeps) + " DGM sub-steps)";
            if (step.guard.kept_redo)
                r.status = "ok (redone by laplacian, " + std::to_string(step.substeps) + " increments)";
            if (r.quality.inverted > 0) r.status = "invalid: " + std::to_string(r.quality.inverted) + " inverted";
            if (v.label == method_name(method) && observer.deformed)  // the paper's methods only
                observer.deformed(v.label, deformed, q);
        } catch (const Error& e) {
            r.status = std::string("failed: ") + e.what();
        }
        if (observer.ended) observer.ended();
        row.methods.push_back(r);
    }
    return row;
}

}  // namespace dgwarp
