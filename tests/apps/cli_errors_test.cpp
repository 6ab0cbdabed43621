// Exit codes and messages of the CLI on bad command lines and damaged files.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "support/test_paths.hpp"

using namespace dgwarp::test;

namespace {


// A small valid SU2 mesh: two triangles, two markers.
const char* good_su2 =
    "NDIME= 2\n"
    "NELEM= 2\n"
    "5 0 1 2 0\n"
    "5 0 2 3 1\n"
    "NPOIN= 4\n"
    "0 0 0\n"
    "1 0 1\n"
    "1 1 2\n"
    "0 1 3\n"
    "NMARK= 2\n"
    "MARKER_TAG= wall\n"
    "MARKER_ELEMS= 1\n"
    "3 0 1\n"
    "MARKER_TAG= farfield\n"
    "MARKER_ELEMS= 3\n"
    "3 1 2\n"
    "3 2 3\n"
    "3 3 0\n";


std::string replaced(std::string text, const std::string& from, const std::string& to) {
    const auto at = text.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    return text.replace(at, from.size(), to);
}

struct Damage {
    const char* name;
    std::string text;
    const char* line;  // the line number the message must name, as ":N:"
};

}  // namespace

TEST(CliErrors, GoodFileIsAccepted) {
    const auto f = write_text(scratch_dir() / "good.su2", good_su2);
    const CommandResult r = run_cli("quality " + quoted(f));
    EXPECT_EQ(r.exit_code, 0) << r.err;
}

TEST(CliErrors, DamagedSu2FilesExitWithCode2NamingFileAndLine) {
    const std::string good = good_su2;
    const std::vector<Damage> damages = {
        {"truncated", good.substr(0, good.find("1 1 2")), ":7:"},  // NPOIN= 4 announced, 2 given
        {"wrong_count", replaced(good, "NELEM= 2", "NELEM= 3"), ":5:"},
        {"bad_number", replaced(good, "1 0 1\n", "1 zero 1\n"), ":7:"},
        {"unknown_element_type", replaced(good, "5 0 2 3 1", "7 0 2 3 1"), ":4:"},
        {"missing_marker_section", good.substr(0, good.find("NMARK")), ":9:"},
    };
    const auto dir = scratch_dir();
    for (const Damage& d : damages) {
        const auto f = write_text(dir / (std::string(d.name) + ".su2"), d.text);
        const CommandResult r = run_cli("quality " + quoted(f));
        EXPECT_EQ(r.exit_code, 2) << d.name << ": " << r.err;
        EXPECT_NE(r.err.find(f.string() + d.line), std::string::npos)
            << d.name << ": message does not name file and line: " << r.err;
        EXPECT_NE(r.err.find("expected"), std::string::npos) << d.name << ": " << r.err;
    }
}

TEST(CliErrors, UsageErrorsExitWithCode1) {
    EXPECT_EQ(run_cli("").exit_code, 1);
    EXPECT_EQ(run_cli("no-such-command").exit_code, 1);
    EXPECT_EQ(run_cli("quality").exit_code, 1);
    EXPECT_EQ(run_cli("quality a.su2 --no-such-flag").exit_code, 1);
    EXPECT_EQ(run_cli("convert a.su2 b.msh --gmsh-version 3").exit_code, 1);
}

TEST(CliErrors, MissingFileAndUnknownFormatExitWithCode2) {
    const auto dir = scratch_dir();
    CommandResult r = run_cli("quality " + quoted(dir / "absent.su2"));
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_NE(r.err.find("absent.su2"), std::string::npos) << r.err;
    const auto f = write_text(dir / "mesh.txt", "hello");
    r = run_cli("quality " + quoted(f));
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_NE(r.err.find(".txt"), std::string::npos) << r.err;
}

TEST(CliErrors, FailedConvertLeavesExistingOutputIntact) {
    const auto dir = scratch_dir();
    const auto out = write_text(dir / "out.su2", "precious");
    const auto bad = write_text(dir / "bad.su2", replaced(good_su2, "1 0 1\n", "1 zero 1\n"));
    EXPECT_EQ(run_cli("convert " + quoted(bad) + " " + quoted(out)).exit_code, 2);
    std::stringstream s;
    s << std::ifstream(out).rdbuf();
    EXPECT_EQ(s.str(), "precious");
}

TEST(CliErrors, AReportLostOnAFullDiskIsAnError) {
    // Issue #27: `info --json > /dev/full` exited 0 with the report lost.
    const auto f = write_text(scratch_dir() / "good.su2", good_su2);
    for (const std::string& args : {"info " + quoted(f) + " --json", "info " + quoted(f), "quality " + quoted(f)}) {
        const CommandResult r = run_command("{ " + cli_path().string() + " " + args + " >/dev/full; }");
        EXPECT_EQ(r.exit_code, 2) << args << "\n" << r.err;
        EXPECT_NE(r.err.find("standard output: the report could not be written: No space left on device"),
                  std::string::npos)
            << r.err;
    }
}

TEST(CliErrors, AZoneOfAFormatWithoutZonesIsAnError) {
    // Issue #27: `--zone 2` on a .msh was ignored with exit 0.
    const auto dir = scratch_dir();
    const auto su2 = write_text(dir / "good.su2", good_su2);
    ASSERT_EQ(run_cli("convert " + quoted(su2) + " " + quoted(dir / "good.msh") + " -q").exit_code, 0);
    CommandResult r = run_cli("info " + quoted(dir / "good.msh") + " --zone 2");
    EXPECT_EQ(r.exit_code, 2) << r.err;
    EXPECT_NE(r.err.find("only SU2 files have several zones"), std::string::npos) << r.err;
    EXPECT_EQ(run_cli("info " + quoted(dir / "good.msh") + " --zone 1").exit_code, 0);
}

TEST(CliErrors, AMeshWithoutCellsIsRefused) {
    // Issue #27: `info` printed "min quality 0.000000 (cell -1)", deform
    // exited 0, convert wrote files dgwarp then refused.
    const auto f = write_text(scratch_dir() / "empty.su2",
                              "NDIME= 2\nNELEM= 0\nNPOIN= 2\n0 0\n1 0\nNMARK= 1\nMARKER_TAG= wall\nMARKER_ELEMS= 1\n3 0 1\n");
    for (const std::string& args : {"info " + quoted(f), "convert " + quoted(f) + " " + quoted(f.parent_path() / "e.vtu")}) {
        const CommandResult r = run_cli(args);
        EXPECT_EQ(r.exit_code, 2) << args << "\n" << r.out;
        EXPECT_NE(r.err.find("empty.su2:2:"), std::string::npos) << r.err;
    }
    EXPECT_FALSE(std::filesystem::exists(f.parent_path() / "e.vtu"));
}

TEST(CliHelp, EveryCommandHasHelpWithExamples) {
    const CommandResult top = run_cli("--help");
    EXPECT_EQ(top.exit_code, 0);
    EXPECT_NE(top.out.find("Exit codes"), std::string::npos);
    for (const char* cmd : {"quality", "convert", "info", "demo"}) {
        const CommandResult r = run_cli(std::string(cmd) + " --help");
        EXPECT_EQ(r.exit_code, 0) << cmd;
        EXPECT_NE(r.out.find("Examples:"), std::string::npos) << cmd << " help has no examples";
        EXPECT_NE(top.out.find(cmd), std::string::npos) << cmd << " missing from top-level help";
    }
}
