// A job's plan (job/job_plan.hpp): built as prepare_for_frames builds it, or
// loaded from a plan file with its own options; a given option that differs
// from a loaded plan's, or a plan of another method than the one asked, is a
// usage error naming it; the reports' plan and boundary objects; a
// decomposed case's processors as node parts.
#include "dgwarp/job/job_plan.hpp"

#include <gtest/gtest.h>

#include <algorithm>

#include "dgwarp/core/error.hpp"
#include "dgwarp/io/motion_file.hpp"
#include "dgwarp/methods/option_table.hpp"
#include "dgwarp/plan/plan_file.hpp"
#include "dgwarp/run/run_deformation.hpp"
#include "io/openfoam/openfoam_test_support.hpp"
#include "support/small_grid_with_hole.hpp"
#include "support/test_paths.hpp"

using namespace dgwarp;
using namespace dgwarp::test;

namespace {

// The small grid's hole lifted by 0.2.
JobInputs lifted_hole() {
    JobInputs in;
    in.mesh = small_grid_with_hole();
    MotionFrame frame;
    frame.markers["rectangle"] = RigidMotion{NodeMotion{{0, 0.2, 0}, {}, {}}};
    in.spec.frames.push_back(frame);
    classify_inputs(in, {});
    measure_original_cells(in, [] {});
    return in;
}

std::vector<double> stepped(const JobInputs& in, const JobPlan& p) {
    const ResolvedFrame motion = resolve_frame(in.mesh, in.spec, in.boundary, 0);
    std::vector<double> out(in.mesh.points.size());
    deform(p.plan, in.mesh.points, motion.motion, out, p.options);
    return out;
}

}  // namespace

TEST(JobPlan, BuiltAsPrepareForFramesBuildsIt) {
    const JobInputs in = lifted_hole();
    PlanRequest r;
    r.method = Method::dg_idw;
    set_method_option(r.options, "length-scale", "auto");
    std::vector<std::string> phases;
    const JobPlan p = plan_job(in, r, [&](const std::string& s) { phases.push_back(s); });
    EXPECT_EQ(phases, std::vector<std::string>{"preparing dg-idw"});
    EXPECT_EQ(p.method, Method::dg_idw);
    EXPECT_TRUE(p.plan_file.empty());
    EXPECT_FALSE(p.slide);  // no sliding marker
    EXPECT_EQ(option_text(*find_method_option("length-scale"), p.options), "auto");
    JobPlan direct = p;
    direct.plan = prepare_for_frames(Method::dg_idw, in.mesh, in.boundary.boundary, r.options);
    EXPECT_EQ(stepped(in, p), stepped(in, direct));
    const nlohmann::json j = plan_json(p);
    EXPECT_EQ(j.at("method"), "dg-idw");
    EXPECT_TRUE(j.at("file").is_null());
    EXPECT_EQ(j.at("dg_idw_weights"), "paper");
    EXPECT_EQ(j.at("bytes"), plan_memory_bytes(p.plan));
    EXPECT_FALSE(j.contains("process_seconds"));
    EXPECT_TRUE(job_plan_warnings(p).empty());  // the outer boundary holds every node
}

TEST(JobPlan, ALoadedPlanKeepsItsOwnOptionsAndRefusesOthersGiven) {
    const JobInputs in = lifted_hole();
    PlanRequest made;
    made.method = Method::dg_harmonic;
    set_method_option(made.options, "harmonic-wall-spacing", "3");
    const JobPlan built = plan_job(in, made);
    const auto file = scratch_dir() / "hole.plan";
    save_plan(file, built.plan);

    PlanRequest r;  // nothing asked: the file's method and options
    r.method = Method::dg_idw;
    r.plan_file = file.string();
    std::vector<std::string> phases;
    const JobPlan loaded = plan_job(in, r, [&](const std::string& s) { phases.push_back(s); });
    EXPECT_EQ(phases, std::vector<std::string>{"loading " + file.string()});
    EXPECT_EQ(loaded.method, Method::dg_harmonic);
    EXPECT_EQ(option_text(*find_method_option("harmonic-wall-spacing"), loaded.options), "3");
    EXPECT_EQ(stepped(in, loaded), stepped(in, built));
    EXPECT_EQ(plan_json(loaded).at("file"), file.string());

    // The same value given again is fine; another is refused, naming the option and the plan's value.
    r.given = {"harmonic-wall-spacing"};
    set_method_option(r.options, "harmonic-wall-spacing", "3");
    EXPECT_NO_THROW(plan_job(in, r));
    set_method_option(r.options, "harmonic-wall-spacing", "5");
    try {
        plan_job(in, r);
        FAIL() << "no error";
    } catch (const UsageError& e) {
        EXPECT_NE(std::string(e.what()).find("--harmonic-wall-spacing: " + file.string() +
                                             " was prepared with --harmonic-wall-spacing 3"),
                  std::string::npos)
            << e.what();
    }
    // An option a plan does not keep (the guard's, at step time) is the run's own.
    r.given = {"harmonic-redo-below"};
    set_method_option(r.options, "harmonic-redo-below", "0.2");
    EXPECT_EQ(option_text(*find_method_option("harmonic-redo-below"), plan_job(in, r).options), "0.2");
    // A plan of another method than the one asked for.
    r.given.clear();
    r.method_given = true;
    EXPECT_THROW(plan_job(in, r), UsageError);
}

TEST(JobPlan, OutsideTheHullOverProcessesIsWhatTheReportsSay) {
    const JobInputs in = lifted_hole();
    PlanRequest r;
    r.method = Method::dg_idw;
    JobPlan p = plan_job(in, r);
    p.outside_hull_over_processes = 3;
    p.process_prepare_seconds = {0.5, 0.25};
    EXPECT_EQ(job_plan_summary(p).outside_hull, 3);
    const std::vector<Warning> w = job_plan_warnings(p);
    ASSERT_EQ(w.size(), 1u);
    EXPECT_EQ(w[0].code, WarningCode::outside_hull);
    EXPECT_EQ(w[0].count, 3);
    EXPECT_NE(w[0].text.find("3 volume nodes are outside"), std::string::npos) << w[0].text;
    EXPECT_EQ(plan_json(p).at("outside_hull"), 3);
    EXPECT_EQ(plan_json(p).at("process_seconds"), (std::vector<double>{0.5, 0.25}));
}

TEST(JobPlan, TheBoundaryObjectCountsTheMovingNodes) {
    const JobInputs in = lifted_hole();
    const nlohmann::json b = boundary_json(in);
    EXPECT_EQ(b.at("nodes"), in.boundary.boundary.nodes.size());
    EXPECT_EQ(b.at("moving_nodes"), std::count(in.boundary.boundary.moving.begin(), in.boundary.boundary.moving.end(), 1));
    EXPECT_EQ(b.at("moving_markers"), std::vector<std::string>{"rectangle"});
    EXPECT_TRUE(b.at("planar").is_null());
}

TEST(JobPlan, ADecomposedCasesProcessorsAreItsNodeParts) {
    JobInputs in;
    in.mesh = read_mesh(openfoam_case("mixed-decomposed"), {}, {}, in.extras);
    ASSERT_TRUE(in.extras.openfoam);
    ASSERT_EQ(in.extras.openfoam->processors.size(), 2u);
    EXPECT_TRUE(processor_node_parts(in, 3).empty());  // as many processes as processors, or none
    const auto parts = processor_node_parts(in, 2);
    ASSERT_EQ(parts.size(), 2u);
    // Every node in a part, the interface's in both.
    std::vector<int> held(static_cast<std::size_t>(in.mesh.num_points()), 0);
    for (const auto& part : parts)
        for (NodeId v : part) ++held.at(static_cast<std::size_t>(v));
    EXPECT_EQ(std::count(held.begin(), held.end(), 0), 0);
    EXPECT_GT(std::count(held.begin(), held.end(), 2), 0);
    JobInputs plain = lifted_hole();
    EXPECT_TRUE(processor_node_parts(plain, 1).empty());
}
