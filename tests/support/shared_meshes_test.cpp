// CI cannot skip the real-mesh tests silently: with CI=true (.ci/run) the
// real SU2 meshes (../shared/meshes/su2) must be there, and every test that
// needs them fails instead of skipping (DGWARP_REQUIRE_SHARED_MESHES).
// Which meshes the folder holds: Su2Meshes.TheFolderHoldsExactlyTheMeshesOfTheReadme.
#include <gtest/gtest.h>

#include <unistd.h>

#include <filesystem>
#include <string>

#include "support/test_paths.hpp"

using namespace dgwarp::test;

namespace {

/// Runs this test binary on the tests `filter` with the environment `env`
/// (assignments for env(1)) and the shared meshes looked for in `meshes`.
CommandResult run_these_tests(const std::string& filter, const std::string& env,
                              const std::filesystem::path& meshes) {
    const std::filesystem::path self = std::filesystem::read_symlink("/proc/self/exe");
    return run_command("env -u CI " + env + " DGWARP_SHARED_MESHES=" + quoted(meshes) + " " + quoted(self) +
                       " --gtest_filter=" + filter);
}

}  // namespace

TEST(SharedMeshes, ArePresentWhenCiIsSet) {
    if (!running_in_ci() && su2_meshes().empty())
        GTEST_SKIP() << su2_meshes_dir() << " is absent; outside CI (CI is not 'true') the real-mesh tests skip";
    EXPECT_FALSE(su2_meshes().empty()) << su2_meshes_dir()
                                       << " holds no SU2 mesh, and CI=true: CI must run the real-mesh tests";
}

TEST(SharedMeshes, WithoutThemCiFailsWhereAUserSkips) {
    const auto empty = scratch_dir();  // a meshes folder without su2/
    for (const std::string filter : {"SharedMeshes.ArePresentWhenCiIsSet", "Su2Meshes.TheFolderHoldsExactlyTheMeshesOfTheReadme"}) {
        SCOPED_TRACE(filter);
        const CommandResult ci = run_these_tests(filter, "CI=true", empty);
        EXPECT_NE(ci.exit_code, 0) << ci.out;
        EXPECT_NE(ci.out.find("CI must run the real-mesh tests"), std::string::npos) << ci.out;
        const CommandResult user = run_these_tests(filter, "", empty);
        EXPECT_EQ(user.exit_code, 0) << user.out;
        EXPECT_NE(user.out.find("[  SKIPPED ] 1 test"), std::string::npos) << user.out;
    }
}
