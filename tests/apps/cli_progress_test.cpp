// The progress line: shown on a terminal (here a pseudo-terminal from
// script(1)), never when standard error is a file or pipe, nor with --quiet.
#include <gtest/gtest.h>

#include "support/rect_box_files.hpp"
#include "support/test_paths.hpp"

using namespace dgwarp::test;

namespace {

// Every command that shows progress, with arguments that run each method.
std::vector<std::string> commands(const RectBoxFiles& f) {
    const std::string m = quoted(f.mesh);
    return {"info " + m,
            "quality " + m + " --reference " + m,
            "convert " + m + " " + quoted(f.dir / "c.msh"),
            "prepare " + m + " -m " + quoted(f.motion) + " -o " + quoted(f.dir / "p.plan"),
            "deform " + m + " -m " + quoted(f.motion) + " -o " + quoted(f.dir / "d.su2") + " --method all"};
}

// A percentage, or a carriage return that is not a terminal's line end
// ("\r\n": a pseudo-terminal turns every "\n" into it): the line's redraws.
bool shows_progress(const std::string& text) {
    for (std::size_t i = 0; i < text.size(); ++i)
        if (text[i] == '%' || (text[i] == '\r' && (i + 1 == text.size() || text[i + 1] != '\n'))) return true;
    return false;
}

// Runs the CLI with standard input, output and error on a pseudo-terminal;
// everything it printed comes back in `out`.
CommandResult run_cli_on_terminal(const std::string& args) {
    return run_command("script -qec \"" + cli_path().string() + " " + args + "\" /dev/null </dev/null");
}

}  // namespace

TEST(CliProgress, NothingWhenStandardErrorIsNotATerminal) {
    const RectBoxFiles f = rect_box_files();
    for (const std::string& c : commands(f)) {
        const CommandResult r = run_cli(c);
        ASSERT_EQ(r.exit_code, 0) << c << "\n" << r.err;
        EXPECT_FALSE(shows_progress(r.err)) << c << "\n" << r.err;
        EXPECT_FALSE(shows_progress(r.out)) << c << "\n" << r.out;
    }
}

TEST(CliProgress, FractionsOnATerminalButNotWithQuiet) {
    ASSERT_EQ(run_command("command -v script").exit_code, 0) << "script(1) (util-linux) not installed";
    const RectBoxFiles f = rect_box_files();
    for (const std::string& c : commands(f)) {
        const CommandResult r = run_cli_on_terminal(c);
        ASSERT_EQ(r.exit_code, 0) << c << "\n" << r.out << r.err;
        EXPECT_NE(r.out.find("%\r"), std::string::npos) << c << "\n" << r.out;  // a fraction, then redrawn
        EXPECT_NE(r.out.find("100%"), std::string::npos) << c << "\n" << r.out;
    }
    const std::string deform = commands(f).back();
    EXPECT_NE(run_cli_on_terminal(deform).out.find("preparing rbf  "), std::string::npos);
    for (const std::string& quiet : {deform + " --quiet", deform + " --json"}) {
        const CommandResult r = run_cli_on_terminal(quiet);
        ASSERT_EQ(r.exit_code, 0) << quiet << "\n" << r.out;
        EXPECT_FALSE(shows_progress(r.out)) << quiet << "\n" << r.out;
    }
}

TEST(CliProgress, FramesAreCountedAsInTheResultRows) {
    // The rows, the JSON and the file names number frames from 0; the
    // progress line names the same frame (and how far the series is).
    ASSERT_EQ(run_command("command -v script").exit_code, 0) << "script(1) (util-linux) not installed";
    const RectBoxFiles f = rect_box_files();
    const auto frames = write_text(f.dir / "frames.json", R"({"frames": [{"markers": {"rectangle": {"translate": [0.1, 0]}}},
                                                                         {"markers": {"rectangle": {"translate": [0.2, 0]}}}]})");
    const CommandResult r = run_cli_on_terminal("deform " + quoted(f.mesh) + " -m " + quoted(frames) + " -o " +
                                                quoted(f.dir / "s.su2"));
    ASSERT_EQ(r.exit_code, 0) << r.out;
    for (const char* shown : {"frame    0", "frame    1", "s_0000.su2", "s_0001.su2", "deforming frame 0 (1 of 2)",
                              "deforming frame 1 (2 of 2)"})
        EXPECT_NE(r.out.find(shown), std::string::npos) << shown << "\n" << r.out;
    EXPECT_EQ(r.out.find("frame 2"), std::string::npos) << r.out;
}
