// `dgwarp quality` and `dgwarp info` end to end: the CLI's figures against an
// independent computation (tests/tools/knupp_quality.py, its own SU2 parser
// and metric), on every real SU2 mesh.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "support/mesh_file_test_name.hpp"
#include "support/test_paths.hpp"

using namespace dgwarp::test;

class CliQualityOnRealMeshes : public ::testing::TestWithParam<std::filesystem::path> {};

TEST_P(CliQualityOnRealMeshes, JsonAgreesWithIndependentComputation) {
    const auto mesh = GetParam();
    const CommandResult cli = run_cli("quality " + quoted(mesh) + " --json");
    ASSERT_EQ(cli.exit_code, 0) << cli.err;
    const auto ours = nlohmann::json::parse(cli.out);
    const CommandResult py = run_command(std::string(DGWARP_PYTHON) + " " +
                                         quoted(source_dir() / "tests/tools/knupp_quality.py") + " " + quoted(mesh));
    ASSERT_EQ(py.exit_code, 0) << py.err;
    const auto theirs = nlohmann::json::parse(py.out);

    const auto& q = ours.at("quality");
    EXPECT_EQ(q.at("cells").get<long>(), theirs.at("cells").get<long>());
    EXPECT_NEAR(q.at("min").get<double>(), theirs.at("min").get<double>(), 1e-9);
    EXPECT_NEAR(q.at("mean").get<double>(), theirs.at("mean").get<double>(), 1e-9);
    EXPECT_EQ(q.at("inverted").get<long>(), theirs.at("inverted").get<long>());
    EXPECT_EQ(ours.at("schema_version").get<int>(), 2);
    EXPECT_EQ(ours.at("mesh").at("cells").get<long>(), q.at("cells").get<long>());

    // The readable form prints the same three figures.
    const CommandResult text = run_cli("quality " + quoted(mesh));
    ASSERT_EQ(text.exit_code, 0) << text.err;
    EXPECT_NE(text.out.find("min quality"), std::string::npos);
    EXPECT_NE(text.out.find("mean quality"), std::string::npos);
    EXPECT_NE(text.out.find("inverted"), std::string::npos);
}

INSTANTIATE_TEST_SUITE_P(Su2Meshes, CliQualityOnRealMeshes, ::testing::ValuesIn(su2_meshes()),
                         mesh_file_test_name);
GTEST_ALLOW_UNINSTANTIATED_PARAMETERIZED_TEST(CliQualityOnRealMeshes);

TEST(CliQuality, ReferenceGivesRatioOfOneForTheSameMesh) {
    const auto dir = scratch_dir();
    ASSERT_EQ(run_cli("demo -o " + quoted(dir)).exit_code, 0);
    const auto mesh = dir / "rect_box.su2";
    const CommandResult r = run_cli("quality " + quoted(mesh) + " --reference " + quoted(mesh) + " --json");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const auto j = nlohmann::json::parse(r.out);
    EXPECT_DOUBLE_EQ(j.at("ratio").at("min").get<double>(), 1.0);
    EXPECT_DOUBLE_EQ(j.at("ratio").at("mean").get<double>(), 1.0);
}

TEST(CliInfo, JsonHasCountsMarkersBoxAndQuality) {
    const auto dir = scratch_dir();
    ASSERT_EQ(run_cli("demo -o " + quoted(dir)).exit_code, 0);
    const CommandResult r = run_cli("info " + quoted(dir / "rect_box.su2") + " --json");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const auto j = nlohmann::json::parse(r.out);
    EXPECT_EQ(j.at("mesh").at("nodes").get<long>(), 2340);
    EXPECT_EQ(j.at("mesh").at("cell_types").at("quadrilateral").get<long>(), 2262);
    EXPECT_EQ(j.at("mesh").at("markers").at(0).at("name"), "rectangle");
    EXPECT_EQ(j.at("mesh").at("markers").at(0).at("nodes").get<long>(), 78);
    EXPECT_DOUBLE_EQ(j.at("bounding_box").at("min").at(0).get<double>(), -20.0);
    EXPECT_DOUBLE_EQ(j.at("bounding_box").at("max").at(1).get<double>(), 20.0);
    EXPECT_EQ(j.at("quality").at("inverted").get<long>(), 0);
}
