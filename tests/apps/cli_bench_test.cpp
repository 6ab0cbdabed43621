// `dgwarp case` and `dgwarp bench` end to end on the small 2D cases.
#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "dgwarp/cases/paper_cases.hpp"
#include "dgwarp/io/mesh_io.hpp"
#include "support/test_paths.hpp"

using namespace dgwarp;
using namespace dgwarp::test;

TEST(CasesCli, CaseWritesTheLibrarysMesh) {
    const auto out = scratch_dir() / "naca0012_case.su2";
    const CommandResult r = run_cli("case naca0012 -o '" + out.string() + "'");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const Mesh written = read_mesh(out);
    const Mesh made = make_case("naca0012");
    EXPECT_EQ(written.num_points(), made.num_points());
    EXPECT_EQ(written.cells, made.cells);
    EXPECT_NE(run_cli("case nope -o '" + out.string() + "'").exit_code, 0);
}

TEST(CasesCli, BenchWritesEveryMotionWithThePapersValues) {
    const auto md = scratch_dir() / "bench.md", js = scratch_dir() / "bench.json";
    // An older file: its tables go, what follows the kept-marker line stays.
    std::ofstream(md) << "old tables\n<!-- dgwarp bench keeps what follows -->\n## Peers\n| a | b |\n";
    const CommandResult r = run_cli("bench --case rect-box --case naca0012 --markdown '" + md.string() + "' --json '" +
                                    js.string() + "' --commit abc123");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    std::ifstream in(js);
    const auto j = nlohmann::json::parse(in);
    ASSERT_EQ(j.at("rows").size(), 5u + 2u);  // rect-box: 4 rotations and a translation; naca0012: 2 motions
    EXPECT_EQ(j.at("commit"), "abc123");
    EXPECT_EQ(j.at("threads"), 1);
    for (const auto& row : j.at("rows")) {
        ASSERT_FALSE(row.at("paper_tables").is_null()) << row.at("motion");
        // Six methods; DG-IDW with L auto, with continuous weights, and followed by untangle.
        ASSERT_EQ(row.at("methods").size(), 9u);
        EXPECT_EQ(row.at("methods").at(4).at("label"), "dg-harmonic");
        EXPECT_EQ(row.at("methods").at(5).at("label"), "laplacian");
        EXPECT_EQ(row.at("methods").at(7).at("label"), "dg-idw continuous");
        EXPECT_EQ(row.at("methods").at(8).at("label"), "dg-idw + untangle");
        for (const auto& m : row.at("methods")) {
            if (!m.at("ran")) continue;
            const double mean = m.at("quality").at("mean"), min = m.at("quality").at("min");
            EXPECT_LE(min, mean);
            EXPECT_LE(mean, 1.0 + 1e-12);
        }
    }
    // Table 5's paper values are printed beside ours.
    const auto& naca = j.at("rows").at(5);
    EXPECT_EQ(naca.at("motion"), "translate");
    EXPECT_DOUBLE_EQ(naca.at("methods").at(0).at("paper").at("mean").get<double>(), 0.908);
    std::stringstream text;
    text << std::ifstream(md).rdbuf();
    EXPECT_NE(text.str().find("paper Table 5"), std::string::npos);
    EXPECT_NE(text.str().find("commit: abc123"), std::string::npos);
    EXPECT_EQ(text.str().find("old tables"), std::string::npos);
    const std::string tail = "\n<!-- dgwarp bench keeps what follows -->\n## Peers\n| a | b |\n";
    ASSERT_GE(text.str().size(), tail.size());
    EXPECT_EQ(text.str().substr(text.str().size() - tail.size()), tail);
}
