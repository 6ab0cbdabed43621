// `dgwarp case NAME --motions DIR`: the case's motions as motion files that
// `dgwarp deform` reads (#17 item 12).
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "support/test_paths.hpp"

using namespace dgwarp::test;

TEST(CliCase, MotionsAreWrittenAsMotionFilesThatDeformReads) {
    const auto dir = scratch_dir();
    const CommandResult r = run_cli("case twisted-bar -o " + quoted(dir / "bar.su2") + " --motions " +
                                    quoted(dir / "motions"));
    ASSERT_EQ(r.exit_code, 0) << r.err;
    for (const char* name : {"twist", "twist-rotate-45"}) {
        const auto file = dir / "motions" / (std::string(name) + ".json");
        EXPECT_NE(r.out.find("wrote " + file.string()), std::string::npos) << r.out;
        const CommandResult d = run_cli("deform " + quoted(dir / "bar.su2") + " -m " + quoted(file) +
                                        " --method dg-harmonic -o " + quoted(dir / (std::string(name) + ".vtu")) +
                                        " --json");
        ASSERT_EQ(d.exit_code, 0) << name << ": " << d.err;
        const auto j = nlohmann::json::parse(d.out);
        EXPECT_EQ(j.at("boundary").at("moving_markers"), std::vector<std::string>{"bar"}) << name;
        EXPECT_GT(j.at("boundary").at("moving_nodes").get<int>(), 0) << name;
    }
    // The rect-box's rotation about the origin by 30 degrees, as a reader sees it.
    const CommandResult rb = run_cli("case rect-box -o " + quoted(dir / "rb.su2") + " --motions " + quoted(dir / "rb") + " -q");
    ASSERT_EQ(rb.exit_code, 0) << rb.err;
    const auto spec = nlohmann::json::parse(slurp(dir / "rb" / "rotate-30.json"));
    EXPECT_EQ(spec.at("markers").at("rectangle").at("rotate").at("angle_deg").get<double>(), 30.0);
    // The motion files are outputs: one that cannot be written is an error before anything is made.
    const CommandResult bad = run_cli("case rect-box -o " + quoted(dir / "x.su2") + " --motions " +
                                      quoted(dir / "bar.su2"));  // a file, not a folder
    EXPECT_NE(bad.exit_code, 0);
    EXPECT_FALSE(std::filesystem::exists(dir / "x.su2"));
}
