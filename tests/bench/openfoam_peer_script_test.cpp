// bench/peers/openfoam.sh without OpenFOAM (--skip-openfoam): on a tiny case,
// the parts that are dgwarp's (convert, the motion field, the dgwarp runs, the
// table) work, and each dgwarp run moves the boundary exactly as prescribed.
#include <gtest/gtest.h>

#include <sstream>

#include "support/test_paths.hpp"

using namespace dgwarp::test;

namespace {

/// The cells of the markdown table row that starts with `start` ("| dgwarp | dg-idw |").
std::vector<std::string> peer_table_row(const std::string& out, const std::string& start) {
    const std::size_t at = out.find("\n" + start);
    if (at == std::string::npos) return {};
    const std::string line = out.substr(at + 1, out.find('\n', at + 1) - at - 1);
    std::vector<std::string> cells;
    std::istringstream in(line.substr(1));
    for (std::string cell; std::getline(in, cell, '|');) {
        const auto b = cell.find_first_not_of(' '), e = cell.find_last_not_of(' ');
        cells.push_back(b == std::string::npos ? "" : cell.substr(b, e - b + 1));
    }
    return cells;
}

std::string peer_script() { return "bash " + quoted(source_dir() / "bench" / "peers" / "openfoam.sh"); }

}  // namespace

TEST(OpenFoamPeerScript, DgwarpPartsRunOnATinyCaseWithoutOpenFoam) {
    const auto dir = scratch_dir();
    const CommandResult r = run_command(
        peer_script() + " --skip-openfoam --work " + quoted(dir) + " --dgwarp " + quoted(cli_path()) +
        " --methods dg-harmonic,dg-idw-untangle --mesh tiny " + quoted(source_dir() / "tests/data/openfoam/mixed") +
        " " + quoted(source_dir() / "examples/motions/openfoam_mixed_lift.json") + " 2>&1");
    ASSERT_EQ(r.exit_code, 0) << r.out << r.err;
    // The OpenFOAM case and the motion OpenFOAM would get.
    EXPECT_TRUE(std::filesystem::exists(dir / "tiny/base/constant/polyMesh/faces"));
    EXPECT_NE(slurp(dir / "tiny/base/0/pointDisplacement").find("class       pointVectorField;"), std::string::npos);
    EXPECT_NE(r.out.find("moving patches: top"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("- load before: "), std::string::npos) << r.out;
    // | tool | method | wall s | CPU s | solve s | peak MB | min | mean | inverted | boundary error | checkMesh | note |
    const auto original = peer_table_row(r.out, "| original |");
    ASSERT_EQ(original.size(), 12u) << r.out;
    EXPECT_EQ(original[6], "0.232");  // dgwarp quality of tests/data/openfoam/mixed (its README's case)
    for (const std::string method : {"dg-harmonic", "dg-idw-untangle"}) {
        const auto row = peer_table_row(r.out, "| dgwarp | " + method + " |");
        ASSERT_EQ(row.size(), 12u) << method << "\n" << r.out;
        EXPECT_GT(std::stod(row[2]), 0.0) << method;  // wall time measured
        EXPECT_GT(std::stod(row[6]), 0.0) << method;  // a valid mesh
        EXPECT_EQ(row[8], "0") << method;             // no cell inverted
        EXPECT_EQ(row[9], "0") << method;             // the boundary moved exactly by the motion field
        EXPECT_EQ(row[10], "") << method;             // no checkMesh without OpenFOAM
    }
    EXPECT_TRUE(peer_table_row(r.out, "| OpenFOAM |").empty());
}

TEST(OpenFoamPeerScript, UnknownArgumentsAreUsageErrors) {
    EXPECT_EQ(run_command(peer_script() + " --skip-openfoam --bogus 2>&1").exit_code, 1);
    EXPECT_EQ(run_command(peer_script() + " --skip-openfoam --methods nope --work " + quoted(scratch_dir()) +
                          " --dgwarp " + quoted(cli_path()) + " --mesh t " +
                          quoted(source_dir() / "tests/data/openfoam/mixed") + " " +
                          quoted(source_dir() / "examples/motions/openfoam_mixed_lift.json") + " 2>&1")
                  .exit_code,
              1);
}
