// step_frame: DG-harmonic's guard judging the one pass on the frame's own
// measure decides and writes exactly what the guard's own measure does
// (deform with a plan prepared with cells), without building that measure.
#include <gtest/gtest.h>

#include <algorithm>
#include <optional>
#include <string>
#include <vector>

#include "dgwarp/core/error.hpp"
#include "dgwarp/methods/dg_harmonic.hpp"
#include "dgwarp/methods/dg_harmonic_guard.hpp"
#include "dgwarp/run/deform_frame.hpp"
#include "dgwarp/run/run_deformation.hpp"
#include "support/case_frame.hpp"

using namespace dgwarp;

namespace {

using test::case_frame;
using test::CaseFrame;

void expect_same_measure(const GuardMeasure& a, const GuardMeasure& b, const std::string& what) {
    EXPECT_EQ(a.inverted, b.inverted) << what;
    EXPECT_EQ(a.inverted_on_boundary, b.inverted_on_boundary) << what;
    EXPECT_EQ(a.min_quality, b.min_quality) << what;
}

}  // namespace

TEST(StepFrame, TheGuardOnTheFramesMeasureDecidesAndWritesAsItsOwnMeasure) {
    // naca0012's 45° turn: the one pass kept; the twisted bar's twist: below
    // the bar, laplacian folds, the one pass kept; the rect-box's 90° turn at
    // 0.99 and at 0: solved again and the better kept, then only checked.
    struct Case {
        std::string name, motion;
        double redo_below;
    };
    for (const Case& k : {Case{"naca0012", "rotate-45", 0.8}, Case{"twisted-bar", "twist", 0.8},
                          Case{"rect-box", "rotate-90", 0.99}, Case{"rect-box", "rotate-90", 0}}) {
        const std::string what = k.name + " " + k.motion + " at " + std::to_string(k.redo_below);
        const CaseFrame c = case_frame(k.name, k.motion);
        MethodOptions options;
        options.dg_harmonic.redo_below = k.redo_below;
        const Plan own = prepare(Method::dg_harmonic, c.mesh.dim, c.mesh.points, c.mesh.cells, c.boundary.boundary);
        std::vector<double> expected(c.mesh.points.size());
        const StepReport e = deform(own, c.mesh.points, c.frame.motion, expected, options);
        ASSERT_TRUE(e.guard.checked) << what;

        const Plan plan = prepare_for_frames(Method::dg_harmonic, c.mesh, c.boundary.boundary);
        const OriginalCells original = measure_original(c.mesh);
        std::vector<double> out(c.mesh.points.size());
        FrameReport report;
        const std::optional<FrameCells> cells =
            step_frame(plan, c.mesh, original, c.boundary.boundary.nodes, nullptr, c.frame.motion, options, out, report);
        EXPECT_EQ(out, expected) << what;
        const DgHarmonicGuardReport& g = report.step.guard;
        EXPECT_TRUE(g.checked) << what;
        EXPECT_EQ(g.bar, e.guard.bar) << what;
        expect_same_measure(g.one_pass, e.guard.one_pass, what + ", one pass");
        EXPECT_EQ(g.redone, e.guard.redone) << what;
        EXPECT_EQ(g.kept_redo, e.guard.kept_redo) << what;
        EXPECT_EQ(g.increments, e.guard.increments) << what;
        EXPECT_EQ(g.boundary_folds, e.guard.boundary_folds) << what;
        EXPECT_EQ(g.redo_error, e.guard.redo_error) << what;
        if (g.redone) expect_same_measure(g.redo, e.guard.redo, what + ", redo");
        EXPECT_EQ(report.step.substeps, e.substeps) << what;
        // The cells returned are those of the points written, and the
        // guard's own measure (its layout) was never built.
        ASSERT_TRUE(cells.has_value()) << what;
        EXPECT_EQ(cells->quality, measure_frame(c.mesh, out, original, c.boundary.boundary.nodes).quality) << what;
        const DgHarmonicGuard& frame_guard = *std::get<DgHarmonicPlan>(plan).guard;
        EXPECT_TRUE(frame_guard.for_frames) << what;
        EXPECT_TRUE(frame_guard.mesh.cells.empty() && frame_guard.mesh.points.empty()) << what;
        EXPECT_TRUE(frame_guard.local_order.empty()) << what;
        EXPECT_GT(report.quality_seconds, 0) << what;
    }
}

TEST(StepFrame, TheBarIsAFractionOfTheLowestValidOriginalQuality) {
    const CaseFrame c = case_frame("rect-box", "rotate-90");
    const OriginalCells original = measure_original(c.mesh);
    double lowest = 1;
    for (double q : original.quality)
        if (q > 0) lowest = std::min(lowest, q);
    EXPECT_EQ(original.valid_min, lowest);
    const Plan plan = prepare_for_frames(Method::dg_harmonic, c.mesh, c.boundary.boundary);
    std::vector<double> out(c.mesh.points.size());
    FrameReport report;
    const std::optional<FrameCells> cells =
        step_frame(plan, c.mesh, original, c.boundary.boundary.nodes, nullptr, c.frame.motion, {}, out, report);
    EXPECT_EQ(report.step.guard.bar, DgHarmonicOptions{}.redo_below * lowest);
    // The guard's measure of a frame from its cells, by brute force.
    const GuardMeasure m = guard_measure_of(*cells, original);
    double min = 1e300;
    std::int64_t inverted = 0;
    for (std::size_t k = 0; k < cells->quality.size(); ++k) {
        if (!(original.quality[k] > 0)) continue;
        min = std::min(min, cells->quality[k]);
        inverted += !(cells->quality[k] > 0);
    }
    EXPECT_EQ(m.min_quality, min);
    EXPECT_EQ(m.inverted, inverted);
}

TEST(StepFrame, ABareDeformStepsAFrameGuardsPlanUnchecked) {
    // A frame guard has no cells to measure with: deform() gives its one pass, and says it was not checked.
    const CaseFrame c = case_frame("rect-box", "rotate-90");
    const Plan plan = prepare_for_frames(Method::dg_harmonic, c.mesh, c.boundary.boundary);
    std::vector<double> out(c.mesh.points.size()), one_pass(c.mesh.points.size());
    EXPECT_FALSE(deform(plan, c.mesh.points, c.frame.motion, out).guard.checked);
    const Plan cloud = prepare(Method::dg_harmonic, c.mesh.dim, c.mesh.points, c.boundary.boundary);
    deform(cloud, c.mesh.points, c.frame.motion, one_pass);
    EXPECT_EQ(out, one_pass);
}

TEST(StepFrame, NoGuardNoMeasureAndOtherMethodsStepAsDeform) {
    const CaseFrame c = case_frame("naca0012", "rotate-45");
    const OriginalCells original = measure_original(c.mesh);
    MethodOptions off;
    off.dg_harmonic.redo_below = -1;
    for (Method method : {Method::dg_idw, Method::dg_harmonic}) {
        const Plan plan = prepare_for_frames(method, c.mesh, c.boundary.boundary);
        std::vector<double> out(c.mesh.points.size()), expected(c.mesh.points.size());
        FrameReport report;
        EXPECT_FALSE(step_frame(plan, c.mesh, original, c.boundary.boundary.nodes, nullptr, c.frame.motion, off, out, report));
        EXPECT_FALSE(report.step.guard.checked);
        deform(plan, c.mesh.points, c.frame.motion, expected, off);
        EXPECT_EQ(out, expected) << method_name(method);
    }
    // A bar that is not a fraction below 1 is refused before the step.
    MethodOptions bad;
    bad.dg_harmonic.redo_below = 1;
    const Plan plan = prepare_for_frames(Method::dg_harmonic, c.mesh, c.boundary.boundary);
    std::vector<double> out(c.mesh.points.size());
    FrameReport report;
    EXPECT_THROW(step_frame(plan, c.mesh, original, c.boundary.boundary.nodes, nullptr, c.frame.motion, bad, out, report),
                 Error);
}

TEST(StepFrame, OutputAliasingTheMeshsPointsGivesTheSameBits) {
    const CaseFrame c = case_frame("rect-box", "rotate-90");
    MethodOptions options;
    options.dg_harmonic.redo_below = 0.99;  // solved again: the redo needs the original points
    const Plan plan = prepare_for_frames(Method::dg_harmonic, c.mesh, c.boundary.boundary);
    const OriginalCells original = measure_original(c.mesh);
    std::vector<double> out(c.mesh.points.size());
    FrameReport report;
    step_frame(plan, c.mesh, original, c.boundary.boundary.nodes, nullptr, c.frame.motion, options, out, report);
    ASSERT_TRUE(report.step.guard.redone);
    // A fresh plan: laplacian's is built on the first redo, from the original points.
    const Plan fresh = prepare_for_frames(Method::dg_harmonic, c.mesh, c.boundary.boundary);
    Mesh in_place = c.mesh;
    FrameReport again;
    step_frame(fresh, in_place, original, c.boundary.boundary.nodes, nullptr, c.frame.motion, options, in_place.points, again);
    EXPECT_EQ(in_place.points, out);
}
