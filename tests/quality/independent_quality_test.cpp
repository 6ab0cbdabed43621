// The quality figures of every real SU2 mesh against an independent
// computation of the same metric: tests/tools/knupp_quality.py, which has its
// own SU2 parser and its own implementation of the formulas and of the
// dominant orientation rule (docs/QUALITY.md).
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "dgwarp/core/error.hpp"
#include "dgwarp/io/mesh_io.hpp"
#include "dgwarp/quality/mesh_quality.hpp"
#include "support/mesh_file_test_name.hpp"
#include "support/test_paths.hpp"

using namespace dgwarp;

class QualityIndependent : public ::testing::TestWithParam<std::filesystem::path> {};

TEST_P(QualityIndependent, SummaryAgreesWithThePythonComputation) {
    const std::filesystem::path& file = GetParam();
    const Mesh mesh = read_mesh(file);
    const QualitySummary s = summarize_quality(cell_qualities(mesh, dominant_orientations(mesh)));

    const std::string script = (test::source_dir() / "tests" / "tools" / "knupp_quality.py").string();
    const test::CommandResult r = test::run_command(std::string(DGWARP_PYTHON) + " '" + script + "' '" + file.string() + "'");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const nlohmann::json expected = nlohmann::json::parse(r.out);

    EXPECT_EQ(s.cells, expected.at("cells").get<std::int64_t>());
    EXPECT_NEAR(s.min, expected.at("min").get<double>(), 1e-9);
    EXPECT_NEAR(s.mean, expected.at("mean").get<double>(), 1e-9);
    EXPECT_EQ(s.inverted, expected.at("inverted").get<std::int64_t>());
}

// The Python tool itself, on the SU2 forms it must read, with hand-computed figures.
TEST(QualityIndependentTool, ReadsSu2FormsAndComputesTheFigures) {
    const auto file = test::scratch_dir() / "forms.su2";
    std::ofstream(file) << "% two zones, tabs, trailing indices, an FFD section\n"
                           "NZONE= 2\n\nIZONE= 1\n"
                           "NDIME=2\n"
                           "NELEM=\t3\n"
                           "9\t0\t1\t2\t3\t0\n"    // unit square: 1
                           "5 4 5 6 1\n"                // 30-60-90 triangle: 0.75
                           "5   7  9  8   2\n"          // clockwise right isosceles: -√3/2 (ties count +1)
                           "NPOIN= 10 10\n"
                           "0 0 0\n1 0 1\n1 1 2\n0 1 3\n"
                           "0\t2\t4\n1.7320508075688772 2 5\n0 3 6\n"
                           "5 0 7\n6 0 8\n5 1 9\n"
                           "NMARK= 1\nMARKER_TAG= wall\nMARKER_ELEMS= 1\n3 0 1\n"
                           "FFD_NBOX= 1\nFFD_CORNER_POINTS= 2\n0 0\n1 1\n"
                           "IZONE= 2\n"
                           "NDIME= 3\nNELEM= 1\n10 0 1 2 3\nNPOIN= 4\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n";
    const std::string tool = std::string(DGWARP_PYTHON) + " '" +
                             (test::source_dir() / "tests" / "tools" / "knupp_quality.py").string() + "' '" +
                             file.string() + "'";
    const test::CommandResult zone1 = test::run_command(tool);
    ASSERT_EQ(zone1.exit_code, 0) << zone1.err;
    const auto j1 = nlohmann::json::parse(zone1.out);
    const double s3 = std::sqrt(3.0);
    EXPECT_EQ(j1.at("cells").get<int>(), 3);
    EXPECT_NEAR(j1.at("min").get<double>(), -s3 / 2, 1e-12);
    EXPECT_NEAR(j1.at("mean").get<double>(), (1 + 0.75 - s3 / 2) / 3, 1e-12);
    EXPECT_EQ(j1.at("inverted").get<int>(), 1);

    const test::CommandResult zone2 = test::run_command(tool + " --zone 2");
    ASSERT_EQ(zone2.exit_code, 0) << zone2.err;
    const auto j2 = nlohmann::json::parse(zone2.out);
    EXPECT_EQ(j2.at("cells").get<int>(), 1);
    EXPECT_NEAR(j2.at("min").get<double>(), 3 * std::cbrt(2.0) / 4.5, 1e-12);
    EXPECT_EQ(j2.at("inverted").get<int>(), 0);
}

INSTANTIATE_TEST_SUITE_P(QualitySu2, QualityIndependent, ::testing::ValuesIn(test::su2_meshes()), test::mesh_file_test_name);
GTEST_ALLOW_UNINSTANTIATED_PARAMETERIZED_TEST(QualityIndependent);
