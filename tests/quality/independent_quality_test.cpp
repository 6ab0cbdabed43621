// The quality figures of every real SU2 mesh against an independent
// computation of the same metric: tests/tools/knupp_quality.py, which has its
// own SU2 parser and its own implementation of the formulas and of the
// dominant orientation rule (docs/QUALITY.md).
#include <gtest/gtest.h>

#include <cctype>
#include <nlohmann/json.hpp>
#include <string>

#include "dgwarp/core/error.hpp"
#include "dgwarp/io/mesh_io.hpp"
#include "dgwarp/quality/mesh_quality.hpp"
#include "support/test_paths.hpp"

using namespace dgwarp;

namespace {

class QualityIndependent : public ::testing::TestWithParam<std::filesystem::path> {};

std::string test_name(const ::testing::TestParamInfo<std::filesystem::path>& info) {
    std::string name = info.param.stem().string();
    for (char& c : name)
        if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
    return name;
}

}  // namespace

TEST_P(QualityIndependent, SummaryAgreesWithThePythonComputation) {
    const std::filesystem::path& file = GetParam();
    Mesh mesh;
    try {
        mesh = read_mesh(file);
    } catch (const FormatError& e) {
        if (std::string(e.what()).find("not built yet") != std::string::npos)
            GTEST_SKIP() << "the SU2 reader is not built yet: " << e.what();
        throw;
    }
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

INSTANTIATE_TEST_SUITE_P(QualitySu2, QualityIndependent, ::testing::ValuesIn(test::su2_meshes()), test_name);
GTEST_ALLOW_UNINSTANTIATED_PARAMETERIZED_TEST(QualityIndependent);
