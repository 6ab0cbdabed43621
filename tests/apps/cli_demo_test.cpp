// `dgwarp demo`: the built-in example writes the default method's result,
// and not an invalid one (issue #27 item 4).
#include <gtest/gtest.h>

#include <filesystem>

#include "support/test_paths.hpp"

using namespace dgwarp::test;

TEST(CliDemo, WritesTheDefaultMethodsResultAndComparesAllFiveMethods) {
    const auto dir = scratch_dir() / "demo";
    const CommandResult r = run_cli("demo -o " + quoted(dir));
    ASSERT_EQ(r.exit_code, 0) << r.err;
    for (const char* method : {"dg-idw", "dgm", "idw", "rbf", "dg-harmonic"})
        EXPECT_NE(r.out.find(std::string("\n") + method + " "), std::string::npos) << method << "\n" << r.out;
    for (const char* name : {"rect_box.su2", "rect_box.png", "rect_box_dg-harmonic.vtu", "rect_box_dg-harmonic.png",
                             "rect_box_dg-harmonic_closeup.png"})
        EXPECT_TRUE(std::filesystem::exists(dir / name)) << name;
    EXPECT_FALSE(std::filesystem::exists(dir / "rect_box_dg-idw.vtu"));  // the demo used to show DG-IDW's
}

TEST(CliDemo, AnInvalidResultIsNotWrittenAndExitsWith3) {
    // --angle 170 wrote DG-IDW's result with 124 inverted cells, exit 0; dg-harmonic
    // keeps 170° valid and inverts cells at 270°.
    const auto dir = scratch_dir() / "demo";
    const CommandResult r = run_cli("demo -o " + quoted(dir) + " --angle 270");
    EXPECT_EQ(r.exit_code, 3) << r.err;
    EXPECT_NE(r.err.find("dg-harmonic (the default method): "), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("inverted cell"), std::string::npos) << r.err;
    EXPECT_TRUE(std::filesystem::exists(dir / "rect_box.su2"));
    EXPECT_FALSE(std::filesystem::exists(dir / "rect_box_dg-harmonic.vtu"));
    EXPECT_FALSE(std::filesystem::exists(dir / "rect_box_dg-harmonic.png"));
}
