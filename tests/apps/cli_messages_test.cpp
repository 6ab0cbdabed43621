// What the CLI prints, read as a new user reads it (issue #27, item 16): flag
// values with the range that is meant, outputs named as what they are, help
// texts that match the README, and no figure for work that was not done.
#include <gtest/gtest.h>

#include <string>

#include "support/rect_box_files.hpp"
#include "support/test_paths.hpp"

using namespace dgwarp::test;

namespace {

bool has(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

}  // namespace

TEST(CliMessages, AFrameNumberIsAWholeNumberFromZero) {
    const auto [dir, mesh, motion] = rect_box_files();
    const std::string base = "motion-field " + quoted(mesh) + " -m " + quoted(motion) + " -o " + quoted(dir / "f.csv");
    for (const char* bad : {"-1", "1e3", "x"}) {
        const CommandResult r = run_cli(base + " --frame " + bad);
        EXPECT_EQ(r.exit_code, 1) << bad;
        EXPECT_TRUE(has(r.err, std::string("expected a frame number, a whole number >= 0 (frames count from 0), got ") +
                                   bad))
            << r.err;
        EXPECT_FALSE(has(r.err, "1797693") || has(r.err, "Could not convert")) << r.err;
    }
    const CommandResult r = run_cli(base + " --frame 3");
    EXPECT_EQ(r.exit_code, 1);
    EXPECT_TRUE(has(r.err, "the motion has 1 frame, frames count from 0; got 3")) << r.err;
}

TEST(CliMessages, AnOutputIsNamedAsWhatItIs) {
    const auto [dir, mesh, motion] = rect_box_files();
    // A file without extension is taken as an OpenFOAM case folder: say so, not "Not a directory".
    write_text(dir / "plain", "x");
    for (const std::string& out : {std::string("/dev/full"), (dir / "plain").string()}) {
        const CommandResult r =
            run_cli("deform " + quoted(mesh) + " -m " + quoted(motion) + " -o " + dgwarp::test::quoted(out));
        EXPECT_EQ(r.exit_code, 1) << out;
        EXPECT_TRUE(has(r.err, out + " is a file without a mesh extension: such a name is an OpenFOAM case folder"))
            << r.err;
        EXPECT_FALSE(has(r.err, "Not a directory")) << r.err;
    }
    EXPECT_EQ(slurp(dir / "plain"), "x");
    // An empty name is not an OpenFOAM case.
    const CommandResult r = run_cli("convert " + quoted(mesh) + " ''");
    EXPECT_EQ(r.exit_code, 1);
    EXPECT_TRUE(has(r.err, "the output name is empty: give a mesh file (.su2")) << r.err;
    EXPECT_FALSE(has(r.err, "OpenFOAM meshes are 3D")) << r.err;
}

TEST(CliMessages, TimesOnlyForWhatHasTimesAndWasDone) {
    const auto [dir, mesh, motion] = rect_box_files();
    // A frames list has no times: no "t=0" on every line; a periodic motion's frames have theirs.
    const auto frames = write_text(dir / "frames.json", R"({"frames": [
        {"markers": {"rectangle": {"translate": [0.01, 0]}}}, {"markers": {"rectangle": {"translate": [0.02, 0]}}}]})");
    CommandResult r = run_cli("deform " + quoted(mesh) + " -m " + quoted(frames) + " -o " + quoted(dir / "f.su2"));
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_TRUE(has(r.out, "frame    1  min ")) << r.out;
    EXPECT_FALSE(has(r.out, "t=")) << r.out;
    const auto periodic = write_text(dir / "periodic.json", R"({"markers": {"rectangle": {"periodic": {
        "pitch": {"amplitude_deg": 2, "frequency": 1.0, "center": [0, 0]}}}}, "time": {"time_step": 0.25, "steps": 2}})");
    r = run_cli("deform " + quoted(mesh) + " -m " + quoted(periodic) + " -o " + quoted(dir / "p.su2"));
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_TRUE(has(r.out, "frame    1  t=0.25 ")) << r.out;
    // Nothing written (the result is invalid): no write time.
    const auto huge = write_text(dir / "huge.json", R"({"markers": {"rectangle": {"translate": [18.8, 0]}}})");
    r = run_cli("deform " + quoted(mesh) + " -m " + quoted(huge) + " -o " + quoted(dir / "h.su2") +
                " --method dg-idw");
    ASSERT_EQ(r.exit_code, 3) << r.err;
    EXPECT_TRUE(has(r.out, "time      deform ")) << r.out;
    EXPECT_FALSE(has(r.out, ", write ")) << r.out;
}

TEST(CliMessages, HelpTextsSayWhatTheReadmeSays) {
    const CommandResult c = run_cli("case --help");
    EXPECT_TRUE(has(c.out, "2 (~865k)")) << c.out;
    EXPECT_FALSE(has(c.out, "826k")) << c.out;
    const CommandResult d = run_cli("deform --help");
    EXPECT_TRUE(has(d.out, "or all (each in turn")) << d.out;
}
