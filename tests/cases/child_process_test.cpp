// run_in_child_process: the work runs in another process, its errors come
// back as Error with their message, and a child past its time is killed.
#include "dgwarp/cases/child_process.hpp"

#include <gtest/gtest.h>

#include <chrono>
#include <cstdlib>
#include <thread>

#include "dgwarp/core/error.hpp"
#include "support/test_paths.hpp"

using namespace dgwarp;

namespace {

/// The message of the Error `f` throws ("" when it throws none).
template <class F>
std::string child_error_message(F&& f) {
    try {
        f();
    } catch (const Error& e) {
        return e.what();
    }
    return "";
}

}  // namespace

TEST(ChildProcess, TheWorkRunsInAChildAndHandsBackThroughFiles) {
    const auto file = test::scratch_dir() / "result.txt";
    int in_this_process = 0;
    run_in_child_process(
        [&] {
            in_this_process = 1;  // the child's copy
            test::write_text(file, "done");
        },
        60, "writing a file");
    EXPECT_EQ(in_this_process, 0);
    EXPECT_EQ(test::slurp(file), "done");
}

TEST(ChildProcess, AnExceptionInTheChildComesBackWithItsMessage) {
    const std::string message = child_error_message(
        [] { run_in_child_process([] { throw MeshError("no such marker 'wing'"); }, 60, "Gmsh's mesh of wing-body"); });
    EXPECT_EQ(message, "Gmsh's mesh of wing-body failed: no such marker 'wing'");
}

TEST(ChildProcess, AChildThatDiesWithoutAMessageIsReported) {
    EXPECT_EQ(child_error_message([] { run_in_child_process([] { std::_Exit(3); }, 60, "the work"); }),
              "the work failed: the child process exited with status 3");
}

TEST(ChildProcess, AChildPastItsTimeIsKilled) {
    const std::string message = child_error_message([] {
        run_in_child_process([] { std::this_thread::sleep_for(std::chrono::seconds(60)); }, 1, "a slow mesh");
    });
    EXPECT_EQ(message, "a slow mesh took more than 1 s");
}
