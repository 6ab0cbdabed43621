// `dgwarp deform` and `dgwarp prepare` end to end on the built-in rect-box
// mesh (written by `dgwarp demo`) and, when present, the real NACA0012 mesh.
#include <gtest/gtest.h>

#include <array>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "dgwarp/io/mesh_io.hpp"
#include "dgwarp/methods/method.hpp"
#include "support/rect_box_files.hpp"
#include "support/test_paths.hpp"

using namespace dgwarp;
using namespace dgwarp::test;

namespace {

const char* huge_translation = R"({"markers": {"rectangle": {"translate": [18.8, 0]}}})";  // to 0.2 from the box

}  // namespace

TEST(CliDeform, WritesTheDeformedMeshAndReportsQualityAndTimes) {
    const auto [dir, mesh, motion] = rect_box_files();
    const CommandResult r = run_cli("deform " + quoted(mesh) + " -m " + quoted(motion) + " -o " +
                                    quoted(dir / "out.su2") + " --json");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const auto j = nlohmann::json::parse(r.out);
    EXPECT_EQ(j.at("command"), "deform");
    EXPECT_EQ(j.at("method"), "dg-harmonic");  // the default: the robust method
    EXPECT_EQ(j.at("boundary").at("moving_markers"), nlohmann::json::array({"rectangle"}));
    EXPECT_EQ(j.at("boundary").at("static_markers"), nlohmann::json::array({"farfield"}));
    ASSERT_EQ(j.at("frames").size(), 1u);
    const auto& f = j.at("frames").at(0);
    EXPECT_EQ(f.at("quality").at("inverted").get<long>(), 0);
    EXPECT_GT(f.at("quality").at("min").get<double>(), 0.0);
    EXPECT_LE(f.at("ratio").at("min").get<double>(), 1.0);
    EXPECT_TRUE(j.at("valid").get<bool>());
    EXPECT_GE(j.at("seconds").at("read").get<double>(), 0.0);
    EXPECT_GE(j.at("plan").at("seconds").get<double>(), 0.0);
    for (const char* phase : {"coarse points", "graph", "locate", "factorise"})
        EXPECT_GE(j.at("plan").at("phase_seconds").at(phase).get<double>(), 0.0) << phase;
    // The whole graph, and the simplices holding a volume node (what a DG-IDW plan keeps).
    EXPECT_GT(j.at("plan").at("graph_simplices_used").get<long>(), 0);
    EXPECT_GE(j.at("plan").at("graph_simplices").get<long>(), j.at("plan").at("graph_simplices_used").get<long>());
    EXPECT_GT(j.at("plan").at("coarse_points").get<long>(), 0);
    EXPECT_GE(f.at("seconds").at("deform").get<double>(), 0.0);

    // The written mesh is the original with moved points: same cells and markers.
    const Mesh before = read_mesh(mesh), after = read_mesh(dir / "out.su2");
    EXPECT_EQ(after.cells, before.cells);
    EXPECT_EQ(after.markers, before.markers);
    EXPECT_NE(after.points, before.points);
}

TEST(CliDeform, VtuOutputCarriesDisplacementAndQuality) {
    const auto [dir, mesh, motion] = rect_box_files();
    ASSERT_EQ(run_cli("deform " + quoted(mesh) + " -m " + quoted(motion) + " -o " + quoted(dir / "out.vtu") + " -q")
                  .exit_code,
              0);
    const CommandResult py = run_command(std::string(DGWARP_PYTHON) + " " +
                                         quoted(source_dir() / "tests/tools/read_vtu.py") + " " +
                                         quoted(dir / "out.vtu"));
    ASSERT_EQ(py.exit_code, 0) << py.err;
    EXPECT_NE(py.out.find("\"displacement\""), std::string::npos);
    EXPECT_NE(py.out.find("\"quality\""), std::string::npos);
    EXPECT_NE(py.out.find("\"quality_ratio\""), std::string::npos);
    // The displacement is the new points minus the original ones: its range per component is theirs.
    const Mesh before = read_mesh(mesh), after = read_mesh(dir / "out.vtu");
    std::vector<double> low(2, 1e300), high(2, -1e300);
    for (std::size_t i = 0; i < before.points.size(); ++i) {
        const double d = after.points[i] - before.points[i];
        low[i % 2] = std::min(low[i % 2], d);
        high[i % 2] = std::max(high[i % 2], d);
    }
    bool found = false;
    const nlohmann::json summary = nlohmann::json::parse(py.out);
    for (const auto& a : summary.at("arrays"))
        if (a.at("name") == "displacement") {
            found = true;
            for (std::size_t k = 0; k < 2; ++k) {
                EXPECT_NEAR(a.at("component_min")[k].get<double>(), low[k], 1e-12) << k;
                EXPECT_NEAR(a.at("component_max")[k].get<double>(), high[k], 1e-12) << k;
            }
            EXPECT_GT(high[0] - low[0] + high[1] - low[1], 0.01);  // it moved
        }
    EXPECT_TRUE(found) << py.out;
}

TEST(CliDeform, InvertedCellsExitWith3AndWriteNothingUnlessAllowed) {
    const auto [dir, mesh, rotation] = rect_box_files();
    const auto motion = write_text(dir / "huge.json", huge_translation);
    const auto out = write_text(dir / "out.su2", "previous result");
    CommandResult r = run_cli("deform " + quoted(mesh) + " -m " + quoted(motion) + " -o " + quoted(out));
    EXPECT_EQ(r.exit_code, 3) << r.err;
    EXPECT_NE(r.err.find("inverted cell"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("worst:"), std::string::npos) << r.err;
    EXPECT_EQ(slurp(out), "previous result");

    r = run_cli("deform " + quoted(mesh) + " -m " + quoted(motion) + " -o " + quoted(out) + " --allow-invalid -q");
    EXPECT_EQ(r.exit_code, 0) << r.err;
    EXPECT_EQ(read_mesh(out).num_points(), 2340u);
}

TEST(CliDeform, TimeSeriesWritesOneFilePerFrame) {
    const auto [dir, mesh, rotation] = rect_box_files();
    const auto motion = write_text(dir / "pitch.json", R"({
        "markers": {"rectangle": {"periodic": {"pitch": {"amplitude_deg": 10, "frequency": 1, "center": [0, 0]}}}},
        "time": {"time_step": 0.125, "steps": 5}})");
    const CommandResult r = run_cli("deform " + quoted(mesh) + " -m " + quoted(motion) + " -o " +
                                    quoted(dir / "frame.su2") + " --json");
    ASSERT_EQ(r.exit_code, 0) << r.err << r.out;
    const auto j = nlohmann::json::parse(r.out);
    ASSERT_EQ(j.at("frames").size(), 5u);
    for (int k = 0; k < 5; ++k) {
        const auto path = dir / ("frame_000" + std::to_string(k) + ".su2");
        EXPECT_TRUE(std::filesystem::exists(path)) << path;
        EXPECT_EQ(j.at("frames").at(k).at("output"), path.string());
    }
    // Step 0 of a sine pitch is the original mesh.
    EXPECT_EQ(read_mesh(dir / "frame_0000.su2").points, read_mesh(mesh).points);
    EXPECT_NE(read_mesh(dir / "frame_0002.su2").points, read_mesh(mesh).points);
}

TEST(CliDeform, AShorterSeriesSaysWhichFramesOfAnEarlierOneAreLeft) {
    // Issue #27: 3 frames after 5 left frame_0003 and frame_0004 without a word.
    const auto [dir, mesh, rotation] = rect_box_files();
    const auto series = [&](int steps) {
        return write_text(dir / ("pitch" + std::to_string(steps) + ".json"),
                          R"({"markers": {"rectangle": {"periodic": {"pitch": {"amplitude_deg": 5, "frequency": 1, "center": [0, 0]}}}},
                              "time": {"time_step": 0.125, "steps": )" + std::to_string(steps) + "}}");
    };
    const auto out = dir / "frame.su2";
    ASSERT_EQ(run_cli("deform " + quoted(mesh) + " -m " + quoted(series(5)) + " -o " + quoted(out) + " -q").exit_code, 0);
    CommandResult r = run_cli("deform " + quoted(mesh) + " -m " + quoted(series(3)) + " -o " + quoted(out));
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(r.err.find("warning: " + (dir / "frame_0003.su2").string() + " ... " + (dir / "frame_0004.su2").string() +
                         " (2 files) are left from an earlier run"),
              std::string::npos)
        << r.err;
    r = run_cli("deform " + quoted(mesh) + " -m " + quoted(series(3)) + " -o " + quoted(out) + " --json");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const auto j = nlohmann::json::parse(r.out);
    ASSERT_TRUE(j.contains("warnings"));
    EXPECT_NE(j.at("warnings").dump().find("frame_0003.su2"), std::string::npos) << j.at("warnings").dump();
    bool coded = false;  // with its code and count, not as text only
    for (const auto& w : j.at("warning_items"))
        coded = coded || (w.at("code") == "stale-frames" && w.at("count") == 2);
    EXPECT_TRUE(coded) << j.at("warning_items").dump();
    // One frame written to frame.su2 itself: the whole series is left.
    r = run_cli("deform " + quoted(mesh) + " -m " + quoted(rotation) + " -o " + quoted(out));
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(r.err.find("(5 files) are left"), std::string::npos) << r.err;
}

TEST(CliDeform, FailureAdviceLeavesOutWhatWasAlreadyGiven) {
    // Issue #27: "--dgm-substep" was advised to a run with --dgm-substep,
    // "--untangle" to one with --untangle; prepare advised "--method rbf",
    // then refused it (only dg-idw and dg-harmonic plans can be saved).
    const auto [dir, mesh, rotation] = rect_box_files();
    const auto motion = write_text(
        dir / "r170.json", R"({"markers": {"rectangle": {"rotate": {"angle_deg": 170, "center": [0, 0]}, "translate": [0.5, 0.25]}}})");
    const std::string base = "deform " + quoted(mesh) + " -m " + quoted(motion) + " -o " + quoted(dir / "o.su2") + " ";
    struct Case {
        std::string options, advice, not_advised;
    };
    for (const Case& c : {Case{"--method dgm --dgm-substep", "For dgm: try --method dg-harmonic", "--dgm-substep"},
                          Case{"--method dg-idw --untangle --length-scale auto", "For dg-idw: try --method dg-harmonic",
                               "--untangle"},
                          Case{"--method dg-idw", "--length-scale auto when", ""},
                          Case{"--method rbf --rbf-radius 5", "For rbf: try --method dg-harmonic, or --untangle",
                               "--rbf-radius"}}) {
        const CommandResult r = run_cli(base + c.options);
        ASSERT_EQ(r.exit_code, 3) << c.options << "\n" << r.err;
        const std::size_t at = r.err.find("For ");
        ASSERT_NE(at, std::string::npos) << r.err;
        const std::string advice = r.err.substr(at);
        EXPECT_NE(advice.find(c.advice), std::string::npos) << c.options << "\n" << advice;
        if (!c.not_advised.empty()) {
            EXPECT_EQ(advice.find(c.not_advised), std::string::npos) << c.options << "\n" << advice;
        }
    }
    const CommandResult r = run_cli("prepare " + quoted(mesh) + " -m " + quoted(motion) + " -o " +
                                    quoted(dir / "p.plan") + " --rbf-radius 1");
    EXPECT_EQ(r.exit_code, 1);
    EXPECT_NE(r.err.find("does not run rbf (only dg-idw and dg-harmonic): drop it"), std::string::npos) << r.err;
    EXPECT_EQ(r.err.find("add --method rbf"), std::string::npos) << r.err;
}

TEST(CliPrepare, SavedPlanGivesBitIdenticalResults) {
    const auto [dir, mesh, motion] = rect_box_files();
    ASSERT_EQ(run_cli("prepare " + quoted(mesh) + " -m " + quoted(motion) + " -o " + quoted(dir / "rb.plan") + " -q")
                  .exit_code,
              0);
    ASSERT_EQ(run_cli("deform " + quoted(mesh) + " -m " + quoted(motion) + " -o " + quoted(dir / "a.su2") + " -q")
                  .exit_code,
              0);
    const CommandResult r = run_cli("deform " + quoted(mesh) + " -m " + quoted(motion) + " --plan " +
                                    quoted(dir / "rb.plan") + " -o " + quoted(dir / "b.su2") + " --json");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_EQ(nlohmann::json::parse(r.out).at("plan").at("file"), (dir / "rb.plan").string());
    EXPECT_EQ(slurp(dir / "a.su2"), slurp(dir / "b.su2"));
}

TEST(CliPrepare, APlanKeepsItsWeightsAndRefusesOthers) {
    const auto [dir, mesh, motion] = rect_box_files();
    const std::string base = quoted(mesh) + " -m " + quoted(motion) + " --method dg-idw";
    ASSERT_EQ(run_cli("prepare " + base + " --dg-idw-weights continuous -o " + quoted(dir / "c.plan") + " -q").exit_code,
              0);
    ASSERT_EQ(run_cli("deform " + base + " --dg-idw-weights continuous -o " + quoted(dir / "a.su2") + " -q").exit_code,
              0);
    ASSERT_EQ(run_cli("deform " + base + " -o " + quoted(dir / "paper.su2") + " -q").exit_code, 0);
    // Without the option, the plan's weights are used (and reported).
    const CommandResult r =
        run_cli("deform " + base + " --plan " + quoted(dir / "c.plan") + " -o " + quoted(dir / "b.su2") + " --json");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_EQ(nlohmann::json::parse(r.out).at("plan").at("dg_idw_weights"), "continuous");
    EXPECT_EQ(slurp(dir / "a.su2"), slurp(dir / "b.su2"));
    EXPECT_NE(slurp(dir / "a.su2"), slurp(dir / "paper.su2"));  // the option changes the result
    // Asking for other weights than the plan holds is a usage error, and nothing is written.
    const CommandResult bad = run_cli("deform " + base + " --plan " + quoted(dir / "c.plan") +
                                      " --dg-idw-weights paper -o " + quoted(dir / "x.su2"));
    EXPECT_EQ(bad.exit_code, 1);
    EXPECT_NE(bad.err.find("prepared with --dg-idw-weights continuous"), std::string::npos) << bad.err;
    EXPECT_FALSE(std::filesystem::exists(dir / "x.su2"));
    EXPECT_EQ(run_cli("deform " + base + " --dg-idw-weights smooth -o " + quoted(dir / "y.su2")).exit_code, 1);
}

// #17 item 5: `prepare --length-scale auto` was shown in the JSON but not kept,
// and `deform --plan` then used L = 1 and inverted 102 cells of this bump.
TEST(CliPrepare, APlanKeepsTheLengthScaleAndTheWeightsAsAndDeformUsesThem) {
    DGWARP_REQUIRE_SHARED_MESHES();
    const auto dir = scratch_dir();
    const std::string base = quoted(su2_meshes_dir() / "deformation_brick_hex_mesh_brick_hex_ffd.su2") + " -m " +
                             quoted(source_dir() / "examples/motions/brick_bump_top.json") + " --method dg-idw";
    ASSERT_EQ(run_cli("prepare " + base + " --length-scale auto --a-translation 5 -o " + quoted(dir / "auto.plan") +
                      " -q")
                  .exit_code,
              0);
    ASSERT_EQ(run_cli("deform " + base + " --length-scale auto --a-translation 5 -o " + quoted(dir / "direct.su2") +
                      " -q")
                  .exit_code,
              0);
    const CommandResult r = run_cli("deform " + base + " --plan " + quoted(dir / "auto.plan") + " -o " +
                                    quoted(dir / "planned.su2") + " --json");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const auto j = nlohmann::json::parse(r.out);
    EXPECT_EQ(j.at("frames")[0].at("quality").at("inverted"), 0);
    EXPECT_EQ(j.at("options").at("length_scale"), "auto");  // the options used are the plan's
    EXPECT_EQ(j.at("options").at("a_translation"), 5.0);
    EXPECT_EQ(slurp(dir / "direct.su2"), slurp(dir / "planned.su2"));
    // The same values again are fine; other values are usage errors naming the plan's, and nothing is written.
    EXPECT_EQ(run_cli("deform " + base + " --plan " + quoted(dir / "auto.plan") + " --length-scale auto -o " +
                      quoted(dir / "same.su2") + " -q")
                  .exit_code,
              0);
    for (const char* option : {"--length-scale 1", "--a-translation 7", "--a-rotation 2"}) {
        const CommandResult bad = run_cli("deform " + base + " --plan " + quoted(dir / "auto.plan") + " " + option +
                                          " -o " + quoted(dir / "x.su2"));
        EXPECT_EQ(bad.exit_code, 1) << option;
        EXPECT_NE(bad.err.find("auto.plan was prepared with"), std::string::npos) << option << ": " << bad.err;
        EXPECT_FALSE(std::filesystem::exists(dir / "x.su2")) << option;
    }
}

// An option of another method would be ignored without a word.
TEST(CliDeform, AnOptionOfAnotherMethodIsAUsageError) {
    const auto [dir, mesh, motion] = rect_box_files();
    const std::string base = quoted(mesh) + " -m " + quoted(motion) + " -o " + quoted(dir / "x.su2");
    CommandResult r = run_cli("deform " + base + " --method dgm --length-scale auto");
    EXPECT_EQ(r.exit_code, 1);
    EXPECT_NE(r.err.find("--length-scale: is an option of dg-idw; it does nothing with dgm"), std::string::npos) << r.err;
    // Without --method the default (dg-harmonic) runs: the error says how to get DG-IDW.
    r = run_cli("deform " + base + " --length-scale auto");
    EXPECT_EQ(r.exit_code, 1);
    EXPECT_NE(r.err.find("does nothing with dg-harmonic (the default method): add --method dg-idw"), std::string::npos)
        << r.err;
    r = run_cli("prepare " + quoted(mesh) + " -m " + quoted(motion) + " -o " + quoted(dir / "p.plan") +
                " --rbf-radius 2");
    EXPECT_EQ(r.exit_code, 1);
    EXPECT_NE(r.err.find("an option of rbf"), std::string::npos) << r.err;
    EXPECT_FALSE(std::filesystem::exists(dir / "x.su2"));
    EXPECT_FALSE(std::filesystem::exists(dir / "p.plan"));
    // With --method all every option applies to one of them.
    EXPECT_EQ(run_cli("deform " + base + " --method all --length-scale auto --rbf-radius 30 -q").exit_code, 0);
    // prepare --help lists the methods whose plans can be saved, not all of them.
    r = run_cli("prepare --help");
    EXPECT_NE(r.out.find("dg-idw or dg-harmonic"), std::string::npos) << r.out;
    EXPECT_EQ(r.out.find("rbf, dg-harmonic"), std::string::npos) << r.out;
}

// #17 item 3: RBF failing inside --method all made a "valid" run with exit 0,
// and the table cut the message mid-word.
TEST(CliDeform, AMethodThatFailsInMethodAllMakesTheRunInvalid) {
    DGWARP_REQUIRE_SHARED_MESHES();
    const auto dir = scratch_dir();
    const auto motion = write_text(dir / "turn5.json",
                                   R"({"markers": {"airfoil": {"rotate": {"angle_deg": 5, "center": [0.25, 0, 0]}}}})");
    const std::string base = "deform " + quoted(su2_meshes_dir() / "rans_naca0012_n0012_225-65.su2") + " -m " + quoted(motion) +
                             " -o " + quoted(dir / "out.su2") + " --method all";
    CommandResult r = run_cli(base + " --json");
    EXPECT_EQ(r.exit_code, 3) << r.err;
    const auto j = nlohmann::json::parse(r.out);
    EXPECT_FALSE(j.at("valid").get<bool>());
    bool rbf_seen = false;
    for (const auto& m : j.at("methods")) {
        if (m.at("method") != "rbf") {
            EXPECT_TRUE(m.at("valid").get<bool>()) << m.at("method");
            continue;
        }
        rbf_seen = true;
        EXPECT_FALSE(m.at("valid").get<bool>());
        EXPECT_NE(m.at("error").get<std::string>().find("--rbf-radius"), std::string::npos) << m.at("error");
    }
    EXPECT_TRUE(rbf_seen);
    EXPECT_FALSE(std::filesystem::exists(dir / "out_rbf.su2"));
    EXPECT_TRUE(std::filesystem::exists(dir / "out_dg-idw.su2"));
    EXPECT_NE(r.err.find("rbf failed"), std::string::npos) << r.err;
    // The table prints the whole message.
    r = run_cli(base);
    EXPECT_EQ(r.exit_code, 3);
    EXPECT_NE(r.out.find("failed: RBF: the 480 x 480 interpolation matrix is numerically not positive definite"),
              std::string::npos)
        << r.out;
    EXPECT_NE(r.out.find("or greedy reduction (rbf_greedy, --rbf-greedy)\n"), std::string::npos) << r.out;
    // --allow-invalid writes inverted meshes, but a method that failed has none: still exit 3.
    EXPECT_EQ(run_cli(base + " --allow-invalid -q").exit_code, 3);
}

TEST(CliPrepare, PlanOfAnotherMeshIsRefused) {
    const auto [dir, mesh, motion] = rect_box_files();
    ASSERT_EQ(run_cli("prepare " + quoted(mesh) + " -m " + quoted(motion) + " -o " + quoted(dir / "rb.plan") + " -q")
                  .exit_code,
              0);
    // The same mesh moved a little is another mesh.
    ASSERT_EQ(run_cli("deform " + quoted(mesh) + " -m " + quoted(motion) + " -o " + quoted(dir / "moved.su2") + " -q")
                  .exit_code,
              0);
    const CommandResult r = run_cli("deform " + quoted(dir / "moved.su2") + " -m " + quoted(motion) + " --plan " +
                                    quoted(dir / "rb.plan") + " -o " + quoted(dir / "x.su2"));
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_NE(r.err.find("plan"), std::string::npos) << r.err;
    EXPECT_FALSE(std::filesystem::exists(dir / "x.su2"));
}

TEST(CliDeform, MethodAllPrintsOneRowPerMethod) {
    const auto [dir, mesh, motion] = rect_box_files();
    CommandResult r = run_cli("deform " + quoted(mesh) + " -m " + quoted(motion) + " -o " + quoted(dir / "out.su2") +
                              " --method all");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    for (Method m : all_methods) {
        const std::string name(method_name(m));
        EXPECT_NE(r.out.find("\n" + name + " "), std::string::npos) << name << " row missing:\n" << r.out;
        EXPECT_TRUE(std::filesystem::exists(dir / ("out_" + name + ".su2"))) << name;
    }
    r = run_cli("deform " + quoted(mesh) + " -m " + quoted(motion) + " -o " + quoted(dir / "out.su2") +
                " --method all --json");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const auto j = nlohmann::json::parse(r.out);
    ASSERT_EQ(j.at("methods").size(), std::size(all_methods));
    for (const auto& m : j.at("methods")) EXPECT_EQ(m.at("frames").size(), 1u) << m.at("method");
    EXPECT_EQ(run_cli("deform " + quoted(mesh) + " -m " + quoted(motion) + " -o x.su2 --method spring").exit_code, 1);
}

TEST(CliDeform, BadMotionFilesExitWith2NamingTheProblem) {
    const auto [dir, mesh, rotation] = rect_box_files();
    const std::vector<std::pair<std::string, std::string>> cases = {
        {R"({"markers": {"wing": {"translate": [1, 0]}}})", "wing"},
        {R"({"markers": {"rectangle": {"translte": [1, 0]}}})", "translte"},
        {R"({"markers": {"rectangle": {"translate": [1, 0)", "bad.json"},
    };
    for (const auto& [text, needle] : cases) {
        const auto motion = write_text(dir / "bad.json", text);
        const CommandResult r =
            run_cli("deform " + quoted(mesh) + " -m " + quoted(motion) + " -o " + quoted(dir / "x.su2"));
        EXPECT_EQ(r.exit_code, 2) << text;
        EXPECT_NE(r.err.find(needle), std::string::npos) << r.err;
    }
}

TEST(CliDeform, Naca0012RotationsKeepEveryCellValid) {
    DGWARP_REQUIRE_SHARED_MESHES();
    const auto dir = scratch_dir();
    const auto mesh = su2_meshes_dir() / "deformation_naca0012_mesh_NACA0012_inv.su2";
    for (int angle : {30, 45, 60, 90}) {
        const auto motion = write_text(dir / "m.json", R"({"markers": {"airfoil": {"rotate": {"angle_deg": )" +
                                                           std::to_string(angle) +
                                                           R"(, "axis": [0, 0, 1], "center": [0.25, 0, 0]}}, "farfield": "fixed"}})");
        const CommandResult r =
            run_cli("deform " + quoted(mesh) + " -m " + quoted(motion) + " -o " + quoted(dir / "x.su2") + " --json");
        ASSERT_EQ(r.exit_code, 0) << angle << ": " << r.err;
        const auto q = nlohmann::json::parse(r.out).at("frames").at(0).at("quality");
        EXPECT_EQ(q.at("inverted").get<long>(), 0) << angle;
        EXPECT_GT(q.at("min").get<double>(), 0.2) << angle;
    }
}

// The top face of SU2's tetrahedral brick turned 10° inside its fixed side
// walls: DG-IDW alone inverts cells next to the rim (exit 3, nothing written);
// --untangle repairs them, reports what it did, and the file written has no
// inverted cell by `dgwarp quality`'s own count.
// #12: the robust method keeps every cell valid on SU2's four bricks with the
// top face turned 10 degrees inside fixed walls, where its step alone folds
// 34 to 132 cells: its untangle last resort repairs them, and says so.
TEST(CliDeform, DgHarmonicsLastResortKeepsTheBricksTopFaceTurnValidAndSaysSo) {
    DGWARP_REQUIRE_SHARED_MESHES();
    const auto dir = scratch_dir();
    const auto motion = source_dir() / "examples" / "motions" / "brick_rotate_top.json";
    for (const char* brick : {"hex", "prism", "pyra", "tets"}) {
        SCOPED_TRACE(brick);
        const auto mesh = su2_meshes_dir() / ("deformation_brick_" + std::string(brick) + "_mesh_brick_" + brick + "_ffd.su2");
        // Without the guard (its laplacian takes seconds here): the last resort is what is tested.
        const std::string base =
            "deform " + quoted(mesh) + " -m " + quoted(motion) + " --method dg-harmonic --harmonic-redo-below -1 -o ";
        CommandResult r = run_cli(base + quoted(dir / "out.su2") + " --json");
        ASSERT_EQ(r.exit_code, 0) << r.err;
        const auto frame = nlohmann::json::parse(r.out).at("frames").at(0);
        EXPECT_EQ(frame.at("quality").at("inverted"), 0);
        EXPECT_GT(frame.at("quality").at("min").get<double>(), 0.02);
        EXPECT_TRUE(frame.at("last_resort").get<bool>());
        EXPECT_GT(frame.at("untangle").at("inverted_before").get<long>(), 0);  // the step alone folds cells
        EXPECT_EQ(frame.at("untangle").at("inverted_after"), 0);
        // Without the last resort the step's own result is seen: invalid.
        r = run_cli(base + quoted(dir / "raw.su2") + " --no-untangle -q");
        EXPECT_EQ(r.exit_code, 3);
        EXPECT_FALSE(std::filesystem::exists(dir / "raw.su2"));
    }
    // The text report names the repair.
    const auto hex = su2_meshes_dir() / "deformation_brick_hex_mesh_brick_hex_ffd.su2";
    const CommandResult text =
        run_cli("deform " + quoted(hex) + " -m " + quoted(motion) + " --method dg-harmonic --harmonic-redo-below -1 -o " +
                quoted(dir / "t.su2"));
    EXPECT_NE(text.out.find("untangle  (dg-harmonic's last resort) inverted cells"), std::string::npos) << text.out;
    // Where nothing folds, there is no repair.
    const auto [rb_dir, rect_box, rotation] = rect_box_files();
    const CommandResult plain = run_cli("deform " + quoted(rect_box) + " -m " + quoted(rotation) +
                                        " --method dg-harmonic --json -o " + quoted(rb_dir / "rb.su2"));
    ASSERT_EQ(plain.exit_code, 0) << plain.err;
    const auto rb_frame = nlohmann::json::parse(plain.out).at("frames").at(0);
    EXPECT_FALSE(rb_frame.at("last_resort").get<bool>());
    EXPECT_TRUE(rb_frame.at("untangle").is_null());
}

namespace {

/// A 3 × 3 grid of unit squares split into triangles (node (i, j) = 4 j + i),
/// markers left, bottom, right and top: the triangles (2, 3, 7) and (8, 13, 12)
/// have every node on the boundary.
std::filesystem::path split_grid_su2(const std::filesystem::path& dir) {
    std::ostringstream su2;
    su2 << "NDIME= 2\nNELEM= 18\n";
    int e = 0;
    for (int j = 0; j < 3; ++j)
        for (int i = 0; i < 3; ++i) {
            const int a = 4 * j + i;
            su2 << "5 " << a << " " << a + 1 << " " << a + 5 << " " << e++ << "\n";
            su2 << "5 " << a << " " << a + 5 << " " << a + 4 << " " << e++ << "\n";
        }
    su2 << "NPOIN= 16\n";
    for (int n = 0; n < 16; ++n) su2 << n % 4 << " " << n / 4 << " " << n << "\n";
    su2 << "NMARK= 4\n";
    const std::pair<const char*, std::array<int, 4>> sides[] = {
        {"left", {0, 4, 8, 12}}, {"bottom", {0, 1, 2, 3}}, {"right", {3, 7, 11, 15}}, {"top", {12, 13, 14, 15}}};
    for (const auto& [name, nodes] : sides) {
        su2 << "MARKER_TAG= " << name << "\nMARKER_ELEMS= 3\n";
        for (int k = 0; k < 3; ++k) su2 << "3 " << nodes[k] << " " << nodes[k + 1] << "\n";
    }
    return write_text(dir / "grid.su2", su2.str());
}

}  // namespace

// A boundary motion that folds a cell with every node on the boundary (here
// the left side pushed through the fixed top and bottom): no method can make
// the frame valid, so dg-harmonic's last resort does not run (on SU2's pin
// array with a pin torn from its walls it searched for 40 s and failed), and
// the report says why.
TEST(CliDeform, ACellFoldedByTheBoundaryMotionItselfIsReportedAndNotUntangled) {
    const auto dir = scratch_dir();
    const auto mesh = split_grid_su2(dir);
    const auto motion = write_text(dir / "push.json", R"({"markers": {"left": {"translate": [2.5, 0]}}})");
    const CommandResult r = run_cli("deform " + quoted(mesh) + " -m " + quoted(motion) + " -o " +
                                    quoted(dir / "out.su2") + " --json");
    EXPECT_EQ(r.exit_code, 3) << r.err;
    EXPECT_FALSE(std::filesystem::exists(dir / "out.su2"));
    EXPECT_NE(r.err.find("every node on the boundary (worst: 13"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("the boundary motion itself folds them"), std::string::npos) << r.err;
    const auto j = nlohmann::json::parse(r.out);
    EXPECT_EQ(j.at("method"), "dg-harmonic");
    const auto& frame = j.at("frames").at(0);
    EXPECT_EQ(frame.at("inverted_on_boundary"), 1);
    EXPECT_GE(frame.at("inverted_by_motion").get<long>(), 1);
    EXPECT_FALSE(frame.at("last_resort").get<bool>());
    EXPECT_TRUE(frame.at("untangle").is_null());
    // The text report names the cell too.
    const CommandResult text = run_cli("deform " + quoted(mesh) + " -m " + quoted(motion) + " -o " +
                                       quoted(dir / "out.su2") + " --allow-invalid");
    EXPECT_EQ(text.exit_code, 0) << text.err;
    EXPECT_NE(text.out.find("inverted with every node on the boundary 1 (cells 13)"), std::string::npos) << text.out;
    // A motion that folds no such cell reports 0.
    const auto small = write_text(dir / "small.json", R"({"markers": {"left": {"translate": [0.2, 0]}}})");
    const CommandResult ok = run_cli("deform " + quoted(mesh) + " -m " + quoted(small) + " -o " +
                                     quoted(dir / "ok.su2") + " --json");
    ASSERT_EQ(ok.exit_code, 0) << ok.err;
    EXPECT_EQ(nlohmann::json::parse(ok.out).at("frames").at(0).at("inverted_on_boundary"), 0);
}

TEST(CliDeform, UntangleRepairsTheBrickTopFaceTurn) {
    DGWARP_REQUIRE_SHARED_MESHES();
    const auto dir = scratch_dir();
    const auto mesh = su2_meshes_dir() / "deformation_brick_tets_mesh_brick_tets_ffd.su2";
    const auto motion = source_dir() / "examples" / "motions" / "brick_rotate_top.json";
    const std::string base = "deform " + quoted(mesh) + " -m " + quoted(motion) + " --method dg-idw --length-scale auto -o ";
    CommandResult r = run_cli(base + quoted(dir / "plain.su2") + " -q");
    EXPECT_EQ(r.exit_code, 3);
    EXPECT_FALSE(std::filesystem::exists(dir / "plain.su2"));

    r = run_cli(base + quoted(dir / "fixed.su2") + " --untangle --json");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const auto frame = nlohmann::json::parse(r.out).at("frames").at(0);
    const auto u = frame.at("untangle");
    EXPECT_GT(u.at("inverted_before").get<long>(), 0);
    EXPECT_EQ(u.at("inverted_after").get<long>(), 0);
    EXPECT_GT(u.at("nodes_moved").get<long>(), 0);
    EXPECT_GT(frame.at("seconds").at("untangle").get<double>(), 0);
    EXPECT_EQ(frame.at("quality").at("inverted").get<long>(), 0);
    const CommandResult q = run_cli("quality " + quoted(dir / "fixed.su2") + " --reference " + quoted(mesh) + " --json");
    ASSERT_EQ(q.exit_code, 0) << q.err;
    EXPECT_EQ(nlohmann::json::parse(q.out).at("quality").at("inverted").get<long>(), 0);

    // A target lifts the worst cells too; without inverted cells and with the
    // default target it reports nothing.
    r = run_cli(base + quoted(dir / "lifted.su2") + " --untangle --untangle-target 0.1 --json");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_GT(nlohmann::json::parse(r.out).at("frames").at(0).at("quality").at("min").get<double>(), 0.05);
    const auto bump = source_dir() / "examples" / "motions" / "brick_tets_bump_top.json";
    r = run_cli("deform " + quoted(mesh) + " -m " + quoted(bump) + " --method dg-idw --length-scale auto -o " + quoted(dir / "b.su2") +
                " --untangle --json");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_TRUE(nlohmann::json::parse(r.out).at("frames").at(0).at("untangle").is_null());
    EXPECT_EQ(run_cli(base + quoted(dir / "x.su2") + " --untangle --untangle-target 1.5").exit_code, 1);
    EXPECT_EQ(run_cli(base + quoted(dir / "x.su2") + " --untangle-target 0.1").exit_code, 1);  // needs --untangle
}

TEST(CliDeform, AFlapNextToItsWingFoldsDgIdwWhichNamesTheFixesAndDgHarmonicStaysValid) {
    // Issue #12 and #17 item 7: the advice names what helps for the method
    // (no longer "split the motion into frames": every frame starts from the
    // original mesh), and dg-harmonic keeps every cell valid.
    const auto dir = scratch_dir();
    const auto mesh = dir / "two-element.su2";
    ASSERT_EQ(run_cli("case two-element -o " + quoted(mesh)).exit_code, 0);
    const auto motion = write_text(dir / "flap20.json", R"({"markers": {"flap": {"rotate": {"angle_deg": -20,
        "center": [0.95, -0.049]}}}})");
    const std::string inputs = quoted(mesh) + " -m " + quoted(motion);
    const CommandResult folded = run_cli("deform " + inputs + " --method dg-idw -o " + quoted(dir / "idw.su2"));
    EXPECT_EQ(folded.exit_code, 3) << folded.err;
    EXPECT_NE(folded.err.find("--method dg-harmonic"), std::string::npos) << folded.err;
    EXPECT_NE(folded.err.find("--untangle"), std::string::npos) << folded.err;
    EXPECT_EQ(folded.err.find("split it into frames"), std::string::npos) << folded.err;
    EXPECT_FALSE(std::filesystem::exists(dir / "idw.su2"));
    // The default method is dg-harmonic.
    const CommandResult robust = run_cli("deform " + inputs + " -o " + quoted(dir / "h.su2") + " --json");
    ASSERT_EQ(robust.exit_code, 0) << robust.err;
    const auto j = nlohmann::json::parse(robust.out);
    EXPECT_EQ(j.at("method"), "dg-harmonic");
    EXPECT_EQ(j.at("frames").at(0).at("quality").at("inverted"), 0);
    EXPECT_GT(j.at("frames").at(0).at("quality").at("min").get<double>(), 0.98 * 0.542);  // measured 0.542
    EXPECT_GT(j.at("plan").at("coarse_points").get<long>(), 0);
}

TEST(CliDeform, ADgHarmonicPlanIsSavedAndReusedWithIdenticalOutput) {
    const auto [dir, mesh, motion] = rect_box_files();
    const std::string inputs = quoted(mesh) + " -m " + quoted(motion);
    ASSERT_EQ(run_cli("prepare " + inputs + " --method dg-harmonic -o " + quoted(dir / "h.plan") + " -q").exit_code, 0);
    ASSERT_EQ(run_cli("deform " + inputs + " --method dg-harmonic -o " + quoted(dir / "direct.su2") + " -q").exit_code, 0);
    // The plan decides the method when --method is not given.
    const CommandResult planned = run_cli("deform " + inputs + " --plan " + quoted(dir / "h.plan") + " -o " +
                                          quoted(dir / "planned.su2") + " --json");
    ASSERT_EQ(planned.exit_code, 0) << planned.err;
    EXPECT_EQ(nlohmann::json::parse(planned.out).at("method"), "dg-harmonic");
    EXPECT_EQ(slurp(dir / "direct.su2"), slurp(dir / "planned.su2"));
    // A conflicting method or prepare-time option is refused.
    EXPECT_EQ(run_cli("deform " + inputs + " --plan " + quoted(dir / "h.plan") + " --method dg-idw -o " +
                      quoted(dir / "x.su2"))
                  .exit_code,
              1);
    EXPECT_EQ(run_cli("deform " + inputs + " --plan " + quoted(dir / "h.plan") + " --harmonic-growth 3 -o " +
                      quoted(dir / "x.su2"))
                  .exit_code,
              1);
    EXPECT_EQ(run_cli("prepare " + inputs + " --method rbf -o " + quoted(dir / "r.plan")).exit_code, 1);
}
