// `dgwarp case NAME --motions DIR`: the case's motions as motion files, which
// `dgwarp deform` turns into what `dgwarp bench` computes, bit for bit.
#include <gtest/gtest.h>

#include <cstring>
#include <fstream>

#include <nlohmann/json.hpp>

#include "dgwarp/cases/paper_cases.hpp"
#include "dgwarp/io/mesh_io.hpp"
#include "dgwarp/methods/method.hpp"
#include "dgwarp/motion/resolve_motion.hpp"
#include "support/test_paths.hpp"

using namespace dgwarp;
using namespace dgwarp::test;

namespace {

/// What `dgwarp bench` computes for the case's motion with DG-IDW (default
/// options): the deformed points, from the library's mesh and motion.
std::vector<double> case_cli_bench_points(const std::string& name, const std::string& motion) {
    const Mesh mesh = make_case(name);
    for (const CaseMotion& cm : case_motions(name, mesh)) {
        if (cm.name != motion) continue;
        const ResolvedBoundary b = resolve_boundary(mesh, cm.spec);
        // The CLI's default method.
        const Plan plan = prepare(Method::dg_harmonic, mesh.dim, mesh.points, b.boundary, MethodOptions{});
        std::vector<double> out(mesh.points.size());
        deform(plan, mesh.points, resolve_frame(mesh, cm.spec, b, 0).motion, out, MethodOptions{});
        return out;
    }
    ADD_FAILURE() << name << " has no motion " << motion;
    return {};
}

}  // namespace

TEST(CaseMotionsCli, DeformWithTheWrittenMotionsGivesTheBenchsPointsBitForBit) {
    const auto dir = scratch_dir();
    // 2D rigid, 2D per node (the twists), a negative angle (the flap), 3D rigid (store: Gmsh).
    const std::vector<std::pair<std::string, std::vector<std::string>>> runs = {
        {"naca0012", {"rotate-45", "translate"}}, {"twisted-bar", {"twist", "twist-rotate-45"}}, {"two-element", {"flap-30"}},
        {"store", {"drop-pitch-10"}}};
    for (const auto& [name, motions] : runs) {
        const auto mesh = dir / (name + ".su2"), folder = dir / (name + "-motions");
        const CommandResult c = run_cli("case " + name + " -o " + quoted(mesh) + " --motions " + quoted(folder));
        ASSERT_EQ(c.exit_code, 0) << c.err;
        // One motion file per motion, each reported.
        for (const CaseMotion& cm : case_motions(name, read_mesh(mesh))) {
            EXPECT_TRUE(std::filesystem::exists(folder / (cm.name + ".json"))) << name << " " << cm.name;
            EXPECT_NE(c.out.find("wrote " + (folder / (cm.name + ".json")).string()), std::string::npos) << c.out;
        }
        for (const std::string& motion : motions) {
            const auto out = dir / (name + "-" + motion + ".su2");
            const CommandResult d =
                run_cli("deform " + quoted(mesh) + " -m " + quoted(folder / (motion + ".json")) + " -o " + quoted(out) +
                        " --allow-invalid");  // bench measures invalid results too
            ASSERT_EQ(d.exit_code, 0) << name << " " << motion << ": " << d.err;
            const std::vector<double> cli = read_mesh(out).points, bench = case_cli_bench_points(name, motion);
            ASSERT_EQ(cli.size(), bench.size()) << name << " " << motion;
            EXPECT_EQ(std::memcmp(cli.data(), bench.data(), cli.size() * sizeof(double)), 0) << name << " " << motion;
        }
    }
    // The twist is a motion per node: its node file is beside the motion file.
    EXPECT_TRUE(std::filesystem::exists(dir / "twisted-bar-motions" / "twist_bar.csv"));
}

TEST(CaseMotionsCli, NeedsAnOutputAndReportsAFolderItCannotMake) {
    const auto dir = scratch_dir();
    const CommandResult none = run_cli("case naca0012");
    EXPECT_EQ(none.exit_code, 1) << none.err;
    EXPECT_NE(none.err.find("--motions"), std::string::npos) << none.err;
    const auto file = write_text(dir / "a-file", "x");
    const CommandResult bad = run_cli("case naca0012 --motions " + quoted(file / "sub"));
    EXPECT_EQ(bad.exit_code, 2) << bad.err;
    EXPECT_NE(bad.err.find("a-file"), std::string::npos) << bad.err;
    // Only the motions: no mesh is written.
    const CommandResult only = run_cli("case rect-box --motions " + quoted(dir / "m"));
    ASSERT_EQ(only.exit_code, 0) << only.err;
    EXPECT_EQ(only.out.find(".su2"), std::string::npos) << only.out;
    EXPECT_TRUE(std::filesystem::exists(dir / "m" / "rotate-30.json"));
}

TEST(CaseRandomCli, WritesTheSceneAndItsMotionAndRefusesMisusedFlags) {
    const auto dir = scratch_dir();
    const std::string mesh = (dir / "scene.su2").string(), motions = (dir / "scene-motions").string();
    const CommandResult r = run_cli("case random --seed 2 --dim 2 -o " + mesh + " --motions " + motions);
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(r.out.find("seed 2, 2D"), std::string::npos) << r.out;
    const Mesh m = read_mesh(mesh);
    EXPECT_EQ(m.markers.back().name, "walls");
    EXPECT_TRUE(std::filesystem::exists(dir / "scene-motions" / "move.json"));
    // deform with the written motion runs (the CLI's default method, with its last resort).
    const CommandResult d = run_cli("deform " + mesh + " -m " + motions + "/move.json -o " +
                                    (dir / "moved.su2").string() + " --method laplacian -q");
    EXPECT_TRUE(d.exit_code == 0 || d.exit_code == 3) << d.err;
    EXPECT_EQ(run_cli("case random -o " + mesh).exit_code, 1);                 // no --seed
    EXPECT_EQ(run_cli("case naca0012 --seed 3 -o " + mesh).exit_code, 1);      // --seed of another case
    EXPECT_EQ(run_cli("case random --seed 1 --dim 4 -o " + mesh).exit_code, 1);
    EXPECT_EQ(run_cli("case naca0012 --dim 3 -o " + mesh).exit_code, 1);       // --dim of another case
}

TEST(BenchRobustnessCli, SummarisesEveryMethodAgainstTheReference) {
    const auto dir = scratch_dir();
    const std::string md = (dir / "robustness.md").string();
    const CommandResult r = run_cli("bench --robustness --seeds 2-3 --dim 2 -q --markdown " + md);
    ASSERT_EQ(r.exit_code, 0) << r.err;
    std::ifstream in(md);
    const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    for (Method m : all_methods) EXPECT_NE(text.find("| " + std::string(method_name(m)) + " |"), std::string::npos) << method_name(m);
    EXPECT_NE(text.find("| 2 | "), std::string::npos);  // a row per seed
    EXPECT_NE(text.find("| 3 | "), std::string::npos);
    // Seed 3: dg-harmonic's one pass falls to 0.025 (original 0.726); its guard keeps laplacian's result.
    EXPECT_NE(text.find(" (L) |"), std::string::npos) << text;
    EXPECT_NE(text.find("laplacian's result kept"), std::string::npos);
    EXPECT_EQ(run_cli("bench --robustness --seeds 5-2").exit_code, 1);
    EXPECT_EQ(run_cli("bench --seeds 1-2").exit_code, 1);  // --seeds needs --robustness
}

TEST(DeformGuardCli, AStepBelowTheBarIsSolvedAgainByLaplacianAndTheReportSaysSo) {
    // Random 2D scene 3: a circle turned 33°; DG-harmonic's one pass keeps
    // every cell but its minimum falls to 0.025 (the original's is 0.726).
    const auto dir = scratch_dir();
    const std::string mesh = (dir / "scene.su2").string(), motion = (dir / "m" / "move.json").string();
    ASSERT_EQ(run_cli("case random --seed 3 -q -o " + mesh + " --motions " + (dir / "m").string()).exit_code, 0);
    CommandResult r = run_cli("deform " + mesh + " -m " + motion + " -o " + (dir / "out.su2").string() + " --json");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    auto frame = nlohmann::json::parse(r.out).at("frames").at(0);
    const auto& guard = frame.at("guard");
    EXPECT_TRUE(guard.at("redone").get<bool>());
    EXPECT_TRUE(guard.at("kept_redo").get<bool>());
    EXPECT_LT(guard.at("one_pass").at("min_quality").get<double>(), guard.at("bar").get<double>());
    EXPECT_EQ(guard.at("redo").at("min_quality"), frame.at("quality").at("min"));
    EXPECT_EQ(guard.at("increments"), frame.at("substeps"));
    EXPECT_FALSE(frame.at("last_resort").get<bool>());
    // The laplacian reference gives the same mesh (its points in no cell stay; the guard's move with the one pass).
    r = run_cli("deform " + mesh + " -m " + motion + " -o " + (dir / "ref.su2").string() + " --method laplacian -q");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const Mesh out = read_mesh(dir / "out.su2"), ref = read_mesh(dir / "ref.su2");
    std::size_t compared = 0;
    for (NodeId n : out.cells.nodes) {
        ASSERT_EQ(out.points[2 * n], ref.points[2 * n]) << "node " << n;
        ASSERT_EQ(out.points[2 * n + 1], ref.points[2 * n + 1]) << "node " << n;
        ++compared;
    }
    EXPECT_GT(compared, 0u);
    // The text report names it; the guard off gives the one pass.
    r = run_cli("deform " + mesh + " -m " + motion + " -o " + (dir / "out.su2").string());
    EXPECT_NE(r.out.find("guard     one pass min 0.0251"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("solved again by laplacian in 4 increments"), std::string::npos) << r.out;
    r = run_cli("deform " + mesh + " -m " + motion + " -o " + (dir / "raw.su2").string() +
                " --harmonic-redo-below -1 --json");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    frame = nlohmann::json::parse(r.out).at("frames").at(0);
    EXPECT_TRUE(frame.at("guard").is_null());
    EXPECT_LT(frame.at("quality").at("min").get<double>(), 0.05);
    // A guard option with another method is a usage error.
    EXPECT_EQ(run_cli("deform " + mesh + " -m " + motion + " -o " + (dir / "x.su2").string() +
                      " --method rbf --harmonic-redo-below 0.3")
                  .exit_code,
              1);
}

TEST(CaseGmshModule, TheCommandLoadsGmshOnlyWhenItMeshesACase) {
    // Gmsh and OpenCASCADE cost 0.2 s and 49 MB at every start of a program
    // linking them: the command loads them (cases/gmsh_cases_module.hpp) only to mesh.
    const CommandResult version = run_command("LD_DEBUG=files " + quoted(cli_path()) + " --version");
    ASSERT_EQ(version.exit_code, 0) << version.err;
    EXPECT_NE(version.err.find("libc.so"), std::string::npos) << "LD_DEBUG printed nothing?";
    EXPECT_EQ(version.err.find("libgmsh"), std::string::npos) << "dgwarp --version loaded Gmsh";
    const auto dir = scratch_dir();
    const CommandResult meshed =
        run_command("LD_DEBUG=files " + quoted(cli_path()) + " case naca0012 -o " + quoted(dir / "n.su2"));
    ASSERT_EQ(meshed.exit_code, 0) << meshed.err;
    EXPECT_NE(meshed.err.find("libdgwarp_gmsh_cases.so"), std::string::npos);
    EXPECT_NE(meshed.err.find("libgmsh"), std::string::npos);
    EXPECT_EQ(read_mesh(dir / "n.su2").num_points(), make_case("naca0012").num_points());
}
