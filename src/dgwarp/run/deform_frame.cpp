#include "dgwarp/run/deform_frame.hpp"

#include <algorithm>
#include <string>
#include <utility>

#include "dgwarp/core/stopwatch.hpp"
#include "dgwarp/repair/last_resort.hpp"
#include "dgwarp/repair/unrepairable_cells.hpp"

namespace dgwarp {

MethodOptions step_options(MethodOptions options, std::int64_t folded_faces) {
    if (folded_faces > 0) options.dg_harmonic.redo_below = -1;
    return options;
}

std::vector<Warning> step_warnings(const StepReport& step) {
    const std::int64_t groups = step.conflicting_shared_vertices;
    if (groups == 0) return {};
    return {{WarningCode::conflicting_shared_motions,
             std::to_string(groups) + " group" +
                 (groups == 1 ? " of boundary nodes at the same coordinates was"
                              : "s of boundary nodes at the same coordinates were") +
                 " given different motions: the nodes separate, and the volume nodes follow the first moving node "
                 "of each group",
             "", groups}};
}

std::vector<Warning> frame_warnings(const ResolvedFrame& motion, const StepReport& step) {
    std::vector<Warning> warnings = motion.warnings;
    for (Warning& w : step_warnings(step)) warnings.push_back(std::move(w));
    return warnings;
}

std::vector<std::int64_t> worst_cells(std::vector<std::int64_t> cells, std::span<const double> quality,
                                      std::size_t count) {
    const auto q = [&](std::int64_t c) { return quality[static_cast<std::size_t>(c)]; };
    std::stable_sort(cells.begin(), cells.end(), [&](auto a, auto b) { return q(a) < q(b); });
    if (cells.size() > count) cells.resize(count);
    return cells;
}

FrameCells measure_frame(const Mesh& mesh, std::span<const double> points, const OriginalCells& original,
                         std::span<const NodeId> fixed) {
    FrameCells c;
    c.quality = cell_qualities(mesh, points, original.orientation);
    c.ratio = quality_ratios(c.quality, original.quality);
    c.inverted = newly_inverted_cells(c.quality, original.quality);
    c.inverted_on_boundary = cells_with_only_fixed_nodes(mesh.cells, fixed, c.inverted);
    return c;
}

FrameCells finish_frame(Method method, const Mesh& mesh, const OriginalCells& original, std::span<const NodeId> fixed,
                        const FrameOptions& options, std::span<double> points, FrameReport& report,
                        const RepairStarted& repair_started) {
    Stopwatch sw;
    if (options.repair == Repair::untangle) {
        if (repair_started) repair_started();
        UntangleOptions untangle_options;
        untangle_options.target_quality = options.untangle_target;
        const UntangleReport u = untangle(mesh.dim, mesh.cells, original.own_orientation, fixed, points, untangle_options);
        if (u.below_target_before > 0) report.untangled = u;
        report.repair_seconds += sw.lap();
    }
    FrameCells cells = measure_frame(mesh, points, original, fixed);
    if (options.repair == Repair::method_default && method == Method::dg_harmonic) {
        // DG-harmonic's last resort (docs/dg-harmonic.md): where the step
        // folded cells (a moving face bounded by fixed walls), repair them
        // locally; not where the boundary motion itself folds a cell (every
        // node on the boundary: run_last_resort does nothing then).
        report.quality_seconds += sw.lap();  // the first measure; the second counts with the repair
        if (!cells.inverted.empty() && repair_started) repair_started();
        report.untangled =
            run_last_resort(mesh.dim, mesh.cells, original.own_orientation, fixed, cells.inverted, points);
        if (report.untangled) {
            report.last_resort = true;
            cells = measure_frame(mesh, points, original, fixed);
        }
        report.repair_seconds += sw.lap();
    }
    report.quality = summarize_quality(cells.quality);
    report.ratio = summarize_ratios(cells.ratio);
    report.inverted_by_motion = static_cast<std::int64_t>(cells.inverted.size());
    report.worst_inverted = worst_cells(cells.inverted, cells.quality, options.worst_count);
    report.inverted_on_boundary = static_cast<std::int64_t>(cells.inverted_on_boundary.size());
    report.worst_on_boundary = worst_cells(cells.inverted_on_boundary, cells.quality, options.worst_count);
    report.quality_seconds += sw.lap();
    return cells;
}

FrameReport deform_frame(const Plan& plan, const Mesh& mesh, const OriginalCells& original,
                         const ResolvedBoundary& boundary, const ResolvedFrame& motion, const MethodOptions& options,
                         const FrameOptions& frame_options, std::span<double> out, FrameCells* cells,
                         const ProgressFn& progress) {
    FrameReport report;
    Stopwatch sw;
    report.step = deform(plan, mesh.points, motion.motion, out, step_options(options, motion.folded_faces), progress);
    report.step_seconds = sw.lap();
    report.warnings = frame_warnings(motion, report.step);
    FrameCells measured =
        finish_frame(plan_method(plan), mesh, original, boundary.boundary.nodes, frame_options, out, report);
    if (cells) *cells = std::move(measured);
    return report;
}

}  // namespace dgwarp
