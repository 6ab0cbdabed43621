#include "dgwarp/run/run_deformation.hpp"

#include <gtest/gtest.h>

#include <vector>

#include "dgwarp/core/error.hpp"
#include "support/small_grid_with_hole.hpp"

using namespace dgwarp;
using test::small_grid_with_hole;

namespace {

// The hole's marker translated by dy in each frame.
MotionSpec lifts(const std::vector<double>& dy) {
    MotionSpec spec;
    for (double d : dy) {
        MotionFrame frame;
        frame.markers["rectangle"] = RigidMotion{NodeMotion{{0, d, 0}, {}, {}}};
        spec.frames.push_back(frame);
    }
    return spec;
}

}  // namespace

TEST(RunDeformation, EveryFrameIsTheOneFrameRunFromTheOriginal) {
    const Mesh mesh = small_grid_with_hole();
    const MotionSpec spec = lifts({0.1, 0.5, 0.2});
    const Deformation d = prepare_deformation(mesh, spec, Method::dg_harmonic);
    EXPECT_EQ(d.original.quality, measure_original(mesh).quality);
    std::vector<std::vector<double>> seen;
    std::vector<double> times;
    RunCallbacks on;
    std::vector<std::size_t> started;
    on.frame_started = [&](std::size_t k) {
        started.push_back(k);
        return ProgressFn{};
    };
    on.frame_done = [&](const FrameView& f) {
        seen.emplace_back(f.points.begin(), f.points.end());
        times.push_back(f.time);
        EXPECT_EQ(f.cells.quality.size(), mesh.cells.size());
        EXPECT_EQ(&f.report, &f.report);
        return true;
    };
    const RunReport r = run_frames(RunContext::of(mesh, spec, d), {}, on);
    ASSERT_EQ(r.frames.size(), 3u);
    EXPECT_TRUE(r.valid());
    EXPECT_EQ(started, (std::vector<std::size_t>{0, 1, 2}));
    // Frame k is deform_frame on frame k alone: no frame depends on the one before.
    for (std::size_t k = 0; k < 3; ++k) {
        const ResolvedFrame motion = resolve_frame(mesh, spec, d.boundary, k);
        std::vector<double> out(mesh.points.size());
        const FrameReport one = deform_frame(d.plan, mesh, d.original, d.boundary, motion, d.options, {}, out);
        EXPECT_EQ(seen[k], out) << "frame " << k;
        EXPECT_EQ(r.frames[k].quality.min, one.quality.min);
        EXPECT_EQ(r.frames[k].ratio.mean, one.ratio.mean);
        EXPECT_EQ(times[k], frame_time(spec, k));
    }
}

TEST(RunDeformation, StopsAtAnInvalidFrameOrWhenTheCallerSays) {
    const Mesh mesh = small_grid_with_hole();
    // Frame 1 pushes the hole through the box's wall: cells fold whatever the method.
    const MotionSpec spec = lifts({0.1, 9.0, 0.1});
    const Deformation d = prepare_deformation(mesh, spec, Method::dg_idw);
    RunOptions options;
    options.frame.repair = Repair::none;
    std::size_t calls = 0;
    RunCallbacks on;
    on.frame_done = [&](const FrameView& f) {
        ++calls;
        EXPECT_EQ(f.report.valid(), f.frame != 1);
        return true;
    };
    const RunReport stopped = run_frames(RunContext::of(mesh, spec, d), options, on);
    EXPECT_EQ(stopped.frames.size(), 2u);
    EXPECT_EQ(calls, 2u);  // the invalid frame is handed over too
    EXPECT_EQ(stopped.first_invalid, 1);
    EXPECT_FALSE(stopped.valid());

    options.stop_at_invalid = false;
    EXPECT_EQ(run_frames(RunContext::of(mesh, spec, d), options, on).frames.size(), 3u);
    on.frame_done = [](const FrameView&) { return false; };
    EXPECT_EQ(run_frames(RunContext::of(mesh, spec, d), options, on).frames.size(), 1u);
}

TEST(RunDeformation, AStepOfTheCallersOwnAndItsWarnings) {
    const Mesh mesh = small_grid_with_hole();
    const MotionSpec spec = lifts({0.2});
    const Deformation d = prepare_deformation(mesh, spec, Method::dg_idw);
    RunCallbacks on;
    int steps = 0;
    on.step = [&](const ResolvedFrame& motion, std::span<double> out, const ProgressFn&) {
        ++steps;
        StepReport r = deform(d.plan, mesh.points, motion.motion, out);
        r.conflicting_shared_vertices = 2;  // as a step would report it
        return r;
    };
    const RunReport r = run_frames(RunContext::of(mesh, spec, d), {}, on);
    EXPECT_EQ(steps, 1);
    ASSERT_EQ(r.frames.size(), 1u);
    ASSERT_EQ(r.frames[0].warnings.size(), 1u);
    EXPECT_EQ(r.frames[0].warnings[0].code, WarningCode::conflicting_shared_motions);
    EXPECT_EQ(r.frames[0].warnings[0].count, 2);
}

TEST(RunDeformation, PrepareRefusesAMotionOfAMarkerTheMeshHasNot) {
    const Mesh mesh = small_grid_with_hole();
    MotionSpec spec;
    MotionFrame frame;
    frame.markers["flap"] = RigidMotion{};
    spec.frames.push_back(frame);
    try {
        prepare_deformation(mesh, spec, Method::dg_idw);
        FAIL() << "no error";
    } catch (const MeshError& e) {
        EXPECT_EQ(e.marker(), "flap");
    }
}
