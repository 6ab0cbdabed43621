// --threads on every command that has it: a count OpenMP cannot start is a
// usage error naming the limit, not a crash (issue #17 item 1: 100000 threads
// segfaulted, 50000 printed libgomp's own error).
#include <gtest/gtest.h>

#include "dgwarp/core/parallel_for.hpp"
#include "support/rect_box_files.hpp"
#include "support/test_paths.hpp"

using namespace dgwarp::test;

TEST(CliThreads, TooManyThreadsIsAUsageErrorNamingTheLimitAndTheCores) {
    const RectBoxFiles f = rect_box_files();
    const std::string m = quoted(f.mesh), motion = quoted(f.motion);
    const std::string limit = "at most " + std::to_string(dgwarp::max_threads());
    const std::string cores = "this machine has " + std::to_string(dgwarp::available_cores()) + " core";
    for (const std::string& command : std::vector<std::string>{
             "deform " + m + " -m " + motion + " -o " + quoted(f.dir / "d.su2"),
          "prepare " + m + " -m " + motion + " -o " + quoted(f.dir / "p.plan"), "quality " + m,
          "bench --case rect-box"}) {
        for (const char* threads : {"100000", "50000", "0", "-3", "two"}) {
            const CommandResult r = run_cli(command + " --threads " + threads);
            EXPECT_EQ(r.exit_code, 1) << command << " --threads " << threads << "\n" << r.err;
            EXPECT_NE(r.err.find("--threads"), std::string::npos) << r.err;
            EXPECT_EQ(r.err.find("libgomp"), std::string::npos) << r.err;
            if (std::string(threads) == "100000") {
                EXPECT_NE(r.err.find(limit), std::string::npos) << r.err;
                EXPECT_NE(r.err.find(cores), std::string::npos) << r.err;
            }
        }
    }
    EXPECT_FALSE(std::filesystem::exists(f.dir / "d.su2"));
    EXPECT_FALSE(std::filesystem::exists(f.dir / "p.plan"));
}

TEST(CliThreads, TheLimitItselfAndTooManyFromTheEnvironmentWork) {
    const RectBoxFiles f = rect_box_files();
    const CommandResult most = run_cli("quality " + quoted(f.mesh) + " --threads " + std::to_string(dgwarp::max_threads()));
    EXPECT_EQ(most.exit_code, 0) << most.err;
    const CommandResult env = run_command("OMP_NUM_THREADS=100000 " + quoted(cli_path()) + " deform " + quoted(f.mesh) +
                                          " -m " + quoted(f.motion) + " -o " + quoted(f.dir / "d.su2") + " -q");
    EXPECT_EQ(env.exit_code, 0) << env.err;
}
