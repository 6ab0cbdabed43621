#include "dgwarp/run/deform_frame.hpp"

#include <algorithm>
#include <cmath>
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
    c.quality = original.layout ? cell_qualities(*original.layout, mesh, points, original.orientation)
                                : cell_qualities(mesh, points, original.orientation);
    c.inverted = newly_inverted_cells(c.quality, original.quality);
    c.inverted_on_boundary = cells_with_only_fixed_nodes(mesh.cells, fixed, c.inverted);
    return c;
}

GuardMeasure guard_measure_of(const FrameCells& cells, const OriginalCells& original) {
    GuardMeasure m;
    m.inverted = static_cast<std::int64_t>(cells.inverted.size());
    m.inverted_on_boundary = static_cast<std::int64_t>(cells.inverted_on_boundary.size());
    bool any = false;
    for (std::size_t c = 0; c < cells.quality.size(); ++c) {
        if (!(original.quality[c] > 0)) continue;
        const double q = std::isnan(cells.quality[c]) ? -1.0 : cells.quality[c];
        if (!any || q < m.min_quality) m.min_quality = q, any = true;
    }
    return m;
}

bool guards_frames(const Plan& plan, const MethodOptions& options) {
    const auto* harmonic = std::get_if<DgHarmonicPlan>(&plan);
    return harmonic && harmonic->guard && options.dg_harmonic.redo_below >= 0;
}

std::optional<FrameCells> step_frame(const Plan& plan, const Mesh& mesh, const OriginalCells& original,
                                     std::span<const NodeId> fixed, const SlidePass* slide,
                                     const BoundaryMotion& given, const MethodOptions& options,
                                     std::span<double> out, FrameReport& report, const ProgressFn& progress) {
    MethodOptions step = options;
    const auto* harmonic = std::get_if<DgHarmonicPlan>(&plan);
    const double redo_below = step.dg_harmonic.redo_below;
    if (harmonic) check_redo_below(redo_below);
    const bool guarded = guards_frames(plan, options);
    if (guarded) step.dg_harmonic.redo_below = -1;  // the one pass: the guard judges it below, on the frame's measure
    // `out` may alias the mesh's points: a redo needs the original ones.
    std::vector<double> kept;
    const std::span<const double> points = guarded ? points_kept_from(mesh.points, out, kept) : mesh.points;
    Stopwatch sw;
    // With sliding markers, their nodes' motion from the first pass.
    BoundaryMotion slid;
    if (slide) {
        slid = given;
        slide_motion(*slide, slid);
    }
    const BoundaryMotion& motion = slide ? slid : given;
    report.step = deform(plan, points, motion, out, step, progress);
    if (slide) apply_slides(slide->slides, mesh.dim, out);  // in their planes to round-off, whatever the method
    report.step_seconds += sw.lap();
    if (!guarded) return std::nullopt;
    DgHarmonicGuardReport& guard = report.step.guard;
    FrameCells cells = measure_frame(mesh, out, original, fixed);
    guard.measure_seconds = sw.lap();
    report.quality_seconds += guard.measure_seconds;
    if (!guard_verdict(*harmonic, guard_measure_of(cells, original), original.valid_min, redo_below, guard))
        return cells;
    std::vector<double> redo(out.size());
    if (guard_redo(*harmonic, mesh.cells, points, motion, redo, guard)) {
        if (slide) apply_slides(slide->slides, mesh.dim, redo);
        FrameCells redone = measure_frame(mesh, redo, original, fixed);
        guard.redo = guard_measure_of(redone, original);
        if (guard_keep(*harmonic, redo, out, guard)) {
            cells = std::move(redone);
            report.step.substeps = guard.increments;
        }
    }
    guard.redo_seconds = sw.lap();
    report.step_seconds += guard.redo_seconds;
    return cells;
}

FrameCells finish_frame(Method method, const Mesh& mesh, const OriginalCells& original, std::span<const NodeId> fixed,
                        const FrameOptions& options, std::span<double> points, FrameReport& report,
                        const RepairStarted& repair_started, std::optional<FrameCells> measured) {
    Stopwatch sw;
    if (options.repair == Repair::untangle) {
        if (repair_started) repair_started();
        UntangleOptions untangle_options;
        untangle_options.target_quality = options.untangle_target;
        const UntangleReport u = untangle(mesh.dim, mesh.cells, original.own_orientation, fixed, points, untangle_options);
        if (u.below_target_before > 0) report.untangled = u;
        report.repair_seconds += sw.lap();
    }
    FrameCells cells = measured && options.repair != Repair::untangle ? std::move(*measured)
                                                                       : measure_frame(mesh, points, original, fixed);
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
    report.ratio = summarize_ratios(cells.quality, original.quality);
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
                         const ProgressFn& progress, const SlidePass* slide) {
    FrameReport report;
    std::optional<FrameCells> stepped =
        step_frame(plan, mesh, original, boundary.boundary.nodes, slide, motion.motion,
                   step_options(options, motion.folded_faces), out, report, progress);
    report.warnings = frame_warnings(motion, report.step);
    FrameCells measured = finish_frame(plan_method(plan), mesh, original, boundary.boundary.nodes, frame_options, out,
                                       report, {}, std::move(stepped));
    if (cells) *cells = std::move(measured);
    return report;
}

}  // namespace dgwarp
