// The README's five-minute tour runs as written, on the shipped files; the
// --help examples name motion files that exist. The tour is read from
// README.md each time, so editing it there keeps it tested.
#include <gtest/gtest.h>

#include <algorithm>
#include <sstream>

#include "support/rect_box_files.hpp"
#include "support/test_paths.hpp"

using namespace dgwarp::test;

namespace {

/// The command lines of the first ```sh block after "## A five-minute tour"
/// in README.md, without their comments.
std::vector<std::string> tour_commands() {
    const std::string readme = slurp(source_dir() / "README.md");
    const std::size_t heading = readme.find("\n## A five-minute tour\n");
    EXPECT_NE(heading, std::string::npos) << "README.md has no tour";
    const std::size_t open = readme.find("```sh\n", heading);
    const std::size_t next_heading = readme.find("\n## ", heading + 1);
    EXPECT_LT(open, next_heading) << "the tour has no ```sh block";
    const std::size_t begin = open + 6, end = readme.find("```", begin);
    std::istringstream block(readme.substr(begin, end - begin));
    std::vector<std::string> commands;
    for (std::string line; std::getline(block, line);) {
        if (const std::size_t hash = line.find(" #"); hash != std::string::npos) line.erase(hash);
        line.erase(line.find_last_not_of(" \t") + 1);
        if (!line.empty()) commands.push_back(line);
    }
    return commands;
}

bool tour_starts_with(const std::string& s, const std::string& prefix) { return s.rfind(prefix, 0) == 0; }

}  // namespace

TEST(ReadmeTour, RunsAsWrittenOnTheShippedFiles) {
    const std::vector<std::string> commands = tour_commands();
    ASSERT_GE(commands.size(), 5u);
    // The tour runs in the repository's folder: here a scratch folder with the
    // shipped examples/ and the built CLI in place of build/dgwarp.
    const auto dir = scratch_dir();
    std::filesystem::create_directory_symlink(source_dir() / "examples", dir / "examples");
    const std::string cli = quoted(cli_path());
    for (const std::string& command : commands) {
        std::string args;
        if (command == "make demo") {
            // What the Makefile's demo target runs once the build is done.
            ASSERT_NE(slurp(source_dir() / "Makefile").find("demo: build\n\t@$(BUILD_DIR)/dgwarp demo\n"),
                      std::string::npos)
                << "the Makefile's demo target changed: teach this test what it runs";
            args = "demo";
        } else if (tour_starts_with(command, "build/dgwarp ")) {
            args = command.substr(13);
        } else {
            FAIL() << "the tour has a line this test does not know how to run: " << command;
        }
        const CommandResult r = run_command("cd " + quoted(dir) + " && " + cli + " " + args);
        EXPECT_EQ(r.exit_code, 0) << "README tour: " << command << "\n" << r.out << r.err;
        // A command that writes says what it wrote (--method all too; a time series per frame, "-> FILE").
        if (command.find(" -o ") != std::string::npos) {
            EXPECT_TRUE(r.out.find("wrote ") != std::string::npos || r.out.find(" -> ") != std::string::npos)
                << "README tour: " << command << "\n" << r.out;
        }
    }
}

TEST(ReadmeTour, MethodAllPrintsTheFilesItWrote) {
    const RectBoxFiles c = rect_box_files();
    const CommandResult r =
        run_cli("deform " + quoted(c.mesh) + " -m " + quoted(c.motion) + " -o " + quoted(c.dir / "cmp.su2") + " --method all");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    for (const char* method : {"dg-idw", "dgm", "idw", "rbf", "dg-harmonic"}) {
        const auto file = c.dir / ("cmp_" + std::string(method) + ".su2");
        EXPECT_TRUE(std::filesystem::exists(file)) << file;
        EXPECT_NE(r.out.find("wrote " + file.string() + "\n"), std::string::npos) << r.out;
    }
}

TEST(ReadmeTour, HelpExamplesNameMotionFilesThatExist) {
    std::size_t named = 0;
    for (const char* command : {"", "deform", "prepare", "check", "info", "quality", "convert", "picture", "case",
                                "bench", "demo"}) {
        const CommandResult r = run_cli(std::string(command) + " --help");
        ASSERT_EQ(r.exit_code, 0) << command;
        std::istringstream help(r.out);
        std::vector<std::string> written_folders;  // by an earlier example's `case ... --motions DIR`
        for (std::string line; std::getline(help, line);) {
            if (line.find("  dgwarp ") != 0) continue;
            std::istringstream words(line);
            for (std::string word, previous; words >> word; previous = word) {
                if (previous == "--motions") written_folders.push_back(word + "/");
                if (previous != "-m" && previous != "--motion") continue;
                ++named;
                const bool written = std::any_of(written_folders.begin(), written_folders.end(),
                                                 [&](const std::string& f) { return tour_starts_with(word, f); });
                EXPECT_TRUE(written || std::filesystem::exists(source_dir() / word))
                    << "dgwarp " << command << " --help names " << word
                    << ", which is not in the repository nor written by an example before it:\n" << line;
            }
        }
    }
    EXPECT_GE(named, 5u);
}
