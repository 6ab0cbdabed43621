// The robustness campaign's summary per method, on scenes made by hand.
#include <gtest/gtest.h>

#include <cmath>

#include "dgwarp/bench/robustness.hpp"

using namespace dgwarp;

namespace {

/// A scene where every method ran valid with min quality `min[method]`
/// (inverted cells where the value is negative).
SceneResult scene(std::uint64_t seed, const std::vector<double>& min) {
    SceneResult s;
    s.seed = seed;
    s.nodes = 100;
    for (Method m : all_methods) {
        SceneRun r;
        r.method = m;
        r.ran = true;
        const double q = min[static_cast<std::size_t>(m)];
        r.inverted = q < 0 ? 3 : 0;
        r.min_quality = q;
        r.near_wall_ratio = 0.9;
        r.step_seconds = 0.002;
        s.runs.push_back(r);
    }
    return s;
}

const MethodSummary& of(const std::vector<MethodSummary>& summary, Method m) {
    return summary[static_cast<std::size_t>(m)];
}

}  // namespace

TEST(Robustness, SummaryRatiosAgainstLaplacianWhereItIsValid) {
    static_assert(std::size(all_methods) == 6);
    // all_methods order: dg-idw, dgm, idw, rbf, dg-harmonic, laplacian.
    std::vector<SceneResult> scenes = {
        scene(1, {0.2, 0.1, 0.3, 0.4, 0.4, 0.4}),
        scene(2, {-0.1, 0.2, 0.2, 0.2, 0.1, 0.4}),
        scene(3, {0.3, 0.3, 0.3, 0.3, 0.3, -0.2}),  // laplacian folds: not in the ratios
    };
    SceneResult failed;  // its mesh could not be made: in no figure
    failed.seed = 4;
    failed.error = "Gmsh failed";
    scenes.push_back(failed);
    scenes[1].runs[static_cast<std::size_t>(Method::dgm)].ran = false;  // dgm failed on scene 2
    scenes[1].runs[static_cast<std::size_t>(Method::dgm)].status = "failed: why";

    const std::vector<MethodSummary> summary = summarize_scenes(scenes);
    ASSERT_EQ(summary.size(), std::size(all_methods));
    const MethodSummary& dg_idw = of(summary, Method::dg_idw);
    EXPECT_EQ(dg_idw.ran, 3);
    EXPECT_EQ(dg_idw.valid, 2);
    EXPECT_EQ(dg_idw.reference_valid, 2);
    EXPECT_EQ(dg_idw.valid_where_reference_valid, 1);
    // Ratios 0.2 / 0.4 = 0.5 and 0 (folded): median 0.25, worst 0 on seed 2.
    EXPECT_DOUBLE_EQ(dg_idw.ratio_median, 0.25);
    EXPECT_DOUBLE_EQ(dg_idw.ratio_worst, 0);
    EXPECT_EQ(dg_idw.worst_seed, 2);
    EXPECT_DOUBLE_EQ(dg_idw.ratio_p5, 0);
    EXPECT_DOUBLE_EQ(dg_idw.step_median_ms, 2);
    const MethodSummary& dgm = of(summary, Method::dgm);
    EXPECT_EQ(dgm.ran, 2);
    EXPECT_EQ(dgm.reference_valid, 1);
    EXPECT_DOUBLE_EQ(dgm.ratio_median, 0.25);
    const MethodSummary& rbf = of(summary, Method::rbf);
    EXPECT_DOUBLE_EQ(rbf.ratio_median, 0.75);  // 1 and 0.5
    EXPECT_EQ(rbf.worst_seed, 2);
    EXPECT_EQ(of(summary, Method::laplacian).valid, 2);
    EXPECT_EQ(reference_invalid_seeds(scenes), std::vector<std::uint64_t>{3});
}

TEST(Robustness, ReportsNameEverySceneAndMethod) {
    std::vector<SceneResult> scenes = {scene(7, {0.2, 0.1, -0.3, 0.4, 0.4, 0.4})};
    scenes[0].description = "two bodies";
    const auto summary = summarize_scenes(scenes);
    RobustnessCampaign c;
    c.first_seed = c.last_seed = 7;
    c.commit = "abc123";
    const std::string md = robustness_markdown(c, scenes, summary, "", 90);
    EXPECT_NE(md.find("seeds 7-7"), std::string::npos);
    EXPECT_NE(md.find("at commit abc123 in 1.5 min"), std::string::npos);
    EXPECT_NE(md.find("| 7 | 100 |"), std::string::npos);
    EXPECT_NE(md.find("**3 inv.**"), std::string::npos);
    EXPECT_NE(md.find("two bodies"), std::string::npos);
    EXPECT_NE(md.find("Scenes where laplacian is not valid: none."), std::string::npos);
    EXPECT_NE(scene_line(scenes[0]).find("| idw -0.300 (3 inverted) |"), std::string::npos);
    const nlohmann::json j = robustness_json(c, scenes, summary, 90);
    ASSERT_EQ(j.at("scenes").size(), 1u);
    EXPECT_EQ(j.at("scenes")[0].at("methods").size(), std::size(all_methods));
    EXPECT_EQ(j.at("summary")[2].at("method"), "idw");
    EXPECT_EQ(j.at("summary")[2].at("valid"), 0);
}
