// One method's run of a job (job/method_run.hpp): every valid frame written
// and reported, an invalid one kept with why and nothing more written unless
// asked, a step's error kept for a job of several methods while an error of
// writing ends the job; the reports' frame and run objects.
#include "dgwarp/job/method_run.hpp"

#include <gtest/gtest.h>

#include <filesystem>

#include "dgwarp/core/error.hpp"
#include "support/small_grid_with_hole.hpp"
#include "support/test_paths.hpp"

using namespace dgwarp;
using namespace dgwarp::test;
namespace fs = std::filesystem;

namespace {

// The small grid's hole lifted by each of `dy`, one frame each.
JobInputs lifted_hole(const std::vector<double>& dy) {
    JobInputs in;
    in.mesh = small_grid_with_hole();
    for (double d : dy) {
        MotionFrame frame;
        frame.markers["rectangle"] = RigidMotion{NodeMotion{{0, d, 0}, {}, {}}};
        in.spec.frames.push_back(frame);
    }
    classify_inputs(in, {});
    measure_original_cells(in, [] {});
    return in;
}

MethodRun planned(const JobInputs& in) {
    MethodRun run;
    PlanRequest r;
    r.method = Method::dg_idw;
    run.planned = plan_job(in, r);
    return run;
}

}  // namespace

TEST(MethodRun, EveryFrameIsWrittenAndReportedInTurn) {
    JobInputs in = lifted_hole({0.1, 0.2});
    MethodRun run = planned(in);
    const fs::path dir = scratch_dir();
    FrameOutputs outputs{dir / "m.su2", 2};
    std::vector<std::size_t> reported;
    run_method(in, run, outputs, {}, {}, [&](JobFrame& f) {
        reported.push_back(f.frame);
        EXPECT_TRUE(fs::exists(f.output)) << "written before it is reported";
        f.process_seconds = {0.5};
    });
    EXPECT_EQ(reported, (std::vector<std::size_t>{0, 1}));
    ASSERT_EQ(run.frames.size(), 2u);
    EXPECT_FALSE(run.invalid);
    EXPECT_EQ(run.frames[1].output, (dir / "m_0001.su2").string());
    EXPECT_EQ(run.frames[1].process_seconds, std::vector<double>{0.5});  // what `reported` added is kept
    const nlohmann::json j = run_json(run);
    EXPECT_EQ(j.at("method"), "dg-idw");
    EXPECT_TRUE(j.at("valid").get<bool>());
    EXPECT_TRUE(j.at("error").is_null());
    ASSERT_EQ(j.at("frames").size(), 2u);
    EXPECT_EQ(j.at("frames")[1].at("output"), run.frames[1].output);
    EXPECT_EQ(j.at("frames")[1].at("frame"), 1);
    EXPECT_EQ(j.at("frames")[1].at("process_seconds"), std::vector<double>{0.5});
    EXPECT_GE(j.at("frames")[1].at("seconds").at("write").get<double>(), 0.0);
}

TEST(MethodRun, AnInvalidFrameIsKeptWithWhyAndNothingMoreIsWrittenUnlessAsked) {
    // Frame 1 pushes the hole through the box's wall: cells fold whatever the method.
    JobInputs in = lifted_hole({0.1, 9.0, 0.1});
    MethodRunOptions options;
    options.frame.repair = Repair::none;
    const fs::path dir = scratch_dir();
    {
        MethodRun run = planned(in);
        FrameOutputs outputs{dir / "m.su2", 3};
        run_method(in, run, outputs, options, {});
        ASSERT_EQ(run.frames.size(), 2u);  // stopped after the invalid frame
        EXPECT_TRUE(run.invalid);
        EXPECT_FALSE(run.failed);
        EXPECT_EQ(run.error, invalid_frame_error(run.frames[1]));
        EXPECT_NE(run.error.find("in frame 1 (worst: "), std::string::npos) << run.error;
        EXPECT_TRUE(run.frames[1].output.empty());
        EXPECT_FALSE(fs::exists(dir / "m_0001.su2"));
        EXPECT_FALSE(run_json(run).at("valid").get<bool>());
    }
    options.write_invalid = true;
    MethodRun run = planned(in);
    FrameOutputs outputs{dir / "w.su2", 3};
    run_method(in, run, outputs, options, {});
    ASSERT_EQ(run.frames.size(), 3u);
    EXPECT_TRUE(run.invalid);
    EXPECT_TRUE(fs::exists(dir / "w_0001.su2"));
    EXPECT_TRUE(fs::exists(dir / "w_0002.su2"));
}

TEST(MethodRun, AStepsErrorIsKeptWhenAskedAnErrorOfWritingNever) {
    JobInputs in = lifted_hole({0.1, 0.2});
    RunCallbacks on;
    on.step = [](const ResolvedFrame&, std::span<double>, const ProgressFn&) -> StepReport {
        throw MeshError("the step broke");
    };
    const fs::path dir = scratch_dir();
    FrameOutputs outputs{dir / "m.su2", 2};
    MethodRun run = planned(in);
    EXPECT_THROW(run_method(in, run, outputs, {}, on), MeshError);

    MethodRunOptions keep;
    keep.keep_step_errors = true;
    run = planned(in);
    run_method(in, run, outputs, keep, on);
    EXPECT_TRUE(run.frames.empty());
    EXPECT_TRUE(run.invalid);
    EXPECT_TRUE(run.failed);
    EXPECT_EQ(run.error, "the step broke");

    // Writing into a folder that is not there ends the job, kept or not.
    FrameOutputs nowhere{dir / "missing" / "m.su2", 2};
    run = planned(in);
    EXPECT_THROW(run_method(in, run, nowhere, keep, {}), Error);
}
