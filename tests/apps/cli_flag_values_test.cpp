// Flag values and what the commands print (issue #17 item 14): every bad
// flag value is a usage error (exit 1) with a readable message, found before
// any work; -q on every command; warnings printed once; a motion that moves
// nothing says so.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <regex>
#include <sstream>

#include "support/rect_box_files.hpp"
#include "support/test_paths.hpp"

using namespace dgwarp::test;

namespace {

/// The lines of `text` that start with "warning:".
std::vector<std::string> flag_values_warning_lines(const std::string& text) {
    std::vector<std::string> lines;
    std::istringstream in(text);
    for (std::string line; std::getline(in, line);)
        if (line.rfind("warning:", 0) == 0) lines.push_back(line);
    return lines;
}

}  // namespace

TEST(CliFlagValues, EveryBadValueIsAUsageErrorWithAReadableMessage) {
    const RectBoxFiles f = rect_box_files();
    const std::string deform = "deform " + quoted(f.mesh) + " -m " + quoted(f.motion) + " -o " + quoted(f.dir / "d.su2");
    const std::string prepare = "prepare " + quoted(f.mesh) + " -m " + quoted(f.motion) + " -o " + quoted(f.dir / "p.plan");
    const std::string picture = "picture " + quoted(f.mesh) + " -o " + quoted(f.dir / "p.png");
    struct Case {
        std::string args;
        const char* flag;
    };
    const std::vector<Case> cases = {
        {deform + " --a-translation nan", "--a-translation"},  // was exit 2 (the library refused it)
        {deform + " --a-translation inf", "--a-translation"},
        {deform + " --a-translation -1", "--a-translation"},  // was a 309-digit range
        {deform + " --a-rotation 1e400", "--a-rotation"},
        {deform + " --method dg-idw --a-translation 1e-310", "--a-translation"},  // made NaN coordinates (#27)
        {deform + " --method dg-idw --a-rotation 1e7", "--a-rotation"},
        {prepare + " --a-rotation nan", "--a-rotation"},
        {deform + " --rbf-radius -1", "--rbf-radius"},
        {deform + " --rbf-greedy inf", "--rbf-greedy"},
        {deform + " --idw-moving-exponent 0", "--idw-moving-exponent"},  // was exit 2
        {deform + " --idw-static-exponent 17", "--idw-static-exponent"},
        {deform + " --harmonic-growth nan", "--harmonic-growth"},
        {deform + " --harmonic-redo-below 1", "--harmonic-redo-below"},
        {deform + " --harmonic-redo-below nan", "--harmonic-redo-below"},
        {deform + " --harmonic-wall-spacing 0", "--harmonic-wall-spacing"},
        {deform + " --length-scale inf", "--length-scale"},  // was exit 2
        {deform + " --length-scale -1", "--length-scale"},
        {deform + " --untangle --untangle-target nan", "--untangle-target"},  // was exit 2
        {deform + " --zone 0", "--zone"},
        {deform + " --zone nan", "--zone"},
        {picture + " --width 0", "--width"},  // was exit 2
        {picture + " --height 100000", "--height"},
        {picture + " --width abc", "--width"},
        {picture + " --zoom nan", "--zoom"},  // was accepted
        {picture + " --window nan 0 0 1", "--window"},  // was exit 2
        {picture + " --window 1 0 0 1", "--window"},
        {"demo -o " + quoted(f.dir / "demo") + " --angle nan", "--angle"},  // was a half table, then exit 2
        {"demo -o " + quoted(f.dir / "demo") + " --angle inf", "--angle"},
        {"case no-such-case -o " + quoted(f.dir / "c.su2"), "no-such-case"},  // was exit 2
        {"case naca0012 --size 5 -o " + quoted(f.dir / "c.su2"), "--size"},  // was exit 2
        {"bench --case no-such-case", "--case"},  // was exit 2
        {"bench --case rect-box --mesh-timeout 0", "--mesh-timeout"},
        {"quality " + quoted(f.mesh) + " --zone -1", "--zone"},
        {"info " + quoted(f.mesh) + " --zone 0", "--zone"},
        {"convert " + quoted(f.mesh) + " " + quoted(f.dir / "c.msh") + " --zone 0", "--zone"},
    };
    const std::regex long_number("[0-9]{20}");
    for (const Case& c : cases) {
        const CommandResult r = run_cli(c.args);
        EXPECT_EQ(r.exit_code, 1) << c.args << "\n" << r.err;
        EXPECT_NE(r.err.find(c.flag), std::string::npos) << c.args << "\n" << r.err;
        EXPECT_FALSE(std::regex_search(r.err, long_number)) << c.args << "\n" << r.err;
        EXPECT_EQ(r.out, "") << c.args << ": printed before the value was refused";
    }
    EXPECT_FALSE(std::filesystem::exists(f.dir / "demo"));
    EXPECT_FALSE(std::filesystem::exists(f.dir / "d.su2"));
}

TEST(CliFlagValues, QuietOnEveryCommand) {
    const RectBoxFiles f = rect_box_files();
    const std::string m = quoted(f.mesh), motion = " -m " + quoted(f.motion);
    const std::vector<std::string> commands = {
        "info " + m,
        "quality " + m + " --histogram",
        "convert " + m + " " + quoted(f.dir / "c.msh"),
        "picture " + m + " -o " + quoted(f.dir / "p.png"),
        "deform " + m + motion + " -o " + quoted(f.dir / "d.su2"),
        "prepare " + m + motion + " -o " + quoted(f.dir / "p.plan"),
        "demo -o " + quoted(f.dir / "demo"),
        "case naca0012 -o " + quoted(f.dir / "naca.su2"),
        "bench --case rect-box --markdown " + quoted(f.dir / "bench.md"),
    };
    for (const std::string& c : commands) {
        const std::string name = c.substr(0, c.find(' '));
        EXPECT_NE(run_cli(name + " --help").out.find("-q,--quiet"), std::string::npos) << name;
        const CommandResult loud = run_cli(c);
        ASSERT_EQ(loud.exit_code, 0) << c << "\n" << loud.err;
        EXPECT_NE(loud.out + loud.err, "") << c;
        for (const char* q : {" -q", " --quiet"}) {
            const CommandResult quiet = run_cli(c + q);
            EXPECT_EQ(quiet.exit_code, 0) << c << q << "\n" << quiet.err;
            EXPECT_EQ(quiet.out, "") << c << q;
            EXPECT_EQ(quiet.err, "") << c << q;
        }
    }
    EXPECT_TRUE(std::filesystem::exists(f.dir / "bench.md"));
}

TEST(CliFlagValues, WarningsArePrintedOnce) {
    const RectBoxFiles f = rect_box_files();
    // Two frames, each moving the rectangle farther than the mesh's diagonal
    // and turning it by more than 180 degrees: four warnings, each once.
    const auto far = write_text(f.dir / "far.json", R"({"frames": [
        {"markers": {"rectangle": {"translate": [100, 0], "rotate": {"angle_deg": 190, "center": [0, 0]}}}},
        {"markers": {"rectangle": {"translate": [200, 0], "rotate": {"angle_deg": 200, "center": [0, 0]}}}}]})");
    const CommandResult r = run_cli("deform " + quoted(f.mesh) + " -m " + quoted(far) + " -o " + quoted(f.dir / "far.su2") +
                                    " --allow-invalid");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    std::vector<std::string> lines = flag_values_warning_lines(r.err);
    std::vector<std::string> motion_lines;
    for (const auto& l : lines)
        if (l.find("far.json") != std::string::npos) motion_lines.push_back(l);
    EXPECT_EQ(motion_lines.size(), 4u) << r.err;
    std::sort(lines.begin(), lines.end());
    EXPECT_EQ(std::adjacent_find(lines.begin(), lines.end()), lines.end()) << "a warning printed twice:\n" << r.err;
    EXPECT_EQ(r.err.find("frame 0: " + far.string() + ", frame 0"), std::string::npos) << r.err;
}

TEST(CliFlagValues, AMotionThatMovesNothingSaysSo) {
    const RectBoxFiles f = rect_box_files();
    for (const char* json : {R"({"markers": {}})", R"({"markers": {"rectangle": "fixed", "farfield": "fixed"}})"}) {
        const auto motion = write_text(f.dir / "still.json", json);
        const std::string args = "deform " + quoted(f.mesh) + " -m " + quoted(motion) + " -o " + quoted(f.dir / "s.su2");
        const CommandResult text = run_cli(args);
        ASSERT_EQ(text.exit_code, 0) << text.err;
        EXPECT_NE(text.err.find("warning: " + motion.string() + ": nothing moves"), std::string::npos) << json << "\n" << text.err;
        const CommandResult js = run_cli(args + " --json");
        ASSERT_EQ(js.exit_code, 0) << js.err;
        EXPECT_NE(nlohmann::json::parse(js.out).at("warnings").dump().find("nothing moves"), std::string::npos) << js.out;
        EXPECT_EQ(js.err, "");
    }
}
