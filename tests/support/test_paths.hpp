#pragma once
// Where the tests find their inputs and tools, and small helpers shared by tests.
#include <filesystem>
#include <string>
#include <vector>

namespace dgwarp::test {

/// The repository's root folder.
std::filesystem::path source_dir();
/// ../shared/meshes/su2 beside the repository (real SU2 meshes), or su2/ in
/// the folder the environment variable DGWARP_SHARED_MESHES names.
std::filesystem::path su2_meshes_dir();
/// Whether the tests run in CI: the environment variable CI is "true" (.ci/run
/// sets it). There the real meshes must be present: a test that needs them
/// fails instead of skipping.
bool running_in_ci();
/// Every .su2 file in su2_meshes_dir(), sorted; empty when the folder is absent.
std::vector<std::filesystem::path> su2_meshes();
/// The dgwarp executable built with the tests.
std::filesystem::path cli_path();
/// A fresh empty folder under the system temp dir, unique to the current test
/// and build folder.
std::filesystem::path scratch_dir();

/// Result of running a command: exit code and what it printed.
struct CommandResult {
    int exit_code = -1;
    std::string out;  // stdout
    std::string err;  // stderr
};
/// Runs `command` through /bin/sh, capturing stdout and stderr.
CommandResult run_command(const std::string& command);
/// Runs the dgwarp CLI with the given argument string.
CommandResult run_cli(const std::string& args);

/// `p` in single quotes, for a shell command line.
std::string quoted(const std::filesystem::path& p);
/// Writes `text` to `path` (replacing it); returns `path`.
std::filesystem::path write_text(const std::filesystem::path& path, const std::string& text);
/// The whole file's bytes ("" when it cannot be read).
std::string slurp(const std::filesystem::path& p);

}  // namespace dgwarp::test

/// Skips the current test when ../shared/meshes/su2 is not beside the
/// repository (users' clones do not have it), and fails it in CI (CI=true),
/// which must run every real-mesh test.
#define DGWARP_REQUIRE_SHARED_MESHES()                                                                   \
    do {                                                                                                 \
        if (::dgwarp::test::su2_meshes().empty()) {                                                      \
            if (::dgwarp::test::running_in_ci())                                                         \
                FAIL() << ::dgwarp::test::su2_meshes_dir().string()                                      \
                       << " holds no SU2 mesh, and CI=true: CI must run the real-mesh tests, not skip them"; \
            GTEST_SKIP() << "../shared/meshes/su2 not found";                                            \
        }                                                                                                \
    } while (0)
