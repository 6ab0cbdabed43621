// Bounded resources: a small file whose header claims 10^12 items, a negative
// count, or an element naming node 10^9 is a ParseError, found before any
// large allocation. Each read runs in a child process whose address space may
// grow by only 256 MiB, so a reader that reserved memory for the count would
// fail there with std::bad_alloc even when the pages are never touched.
#include <gtest/gtest.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstring>
#include <fstream>
#include <functional>
#include <iterator>
#include <string>
#include <vector>

#include "dgwarp/core/error.hpp"
#include "dgwarp/core/parallel_for.hpp"
#include "dgwarp/io/gmsh/gmsh.hpp"
#include "dgwarp/io/motion_file.hpp"
#include "dgwarp/plan/plan_file.hpp"
#include "dgwarp/io/su2/su2.hpp"
#include "fuzz_checks.hpp"
#include "support/box_in_box.hpp"
#include "support/test_paths.hpp"

#if defined(__SANITIZE_ADDRESS__)
#define DGWARP_TEST_ASAN 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define DGWARP_TEST_ASAN 1
#endif
#endif

using namespace dgwarp;

namespace {

// How the read in the child ended.
enum class Outcome { parse_error = 0, no_error = 1, bad_alloc = 2, other_error = 3, limit_failed = 4 };

/// Runs `read` in a child process whose address space may grow by at most
/// 256 MiB; returns how it ended (or -1 when the child crashed).
/// Under AddressSanitizer, whose shadow memory needs terabytes of address
/// space, the limit cannot be set: `read` then runs here, unlimited (ASan
/// still aborts on an allocation beyond its maximum).
int outcome_with_little_memory(const std::function<void()>& read) {
    const auto run = [&]() -> int {
        try {
            read();
        } catch (const ParseError&) {
            return static_cast<int>(Outcome::parse_error);
        } catch (const std::bad_alloc&) {
            return static_cast<int>(Outcome::bad_alloc);
        } catch (...) {
            return static_cast<int>(Outcome::other_error);
        }
        return static_cast<int>(Outcome::no_error);
    };
#ifdef DGWARP_TEST_ASAN
    return run();
#else
    constexpr std::size_t headroom = std::size_t{256} << 20;
    const pid_t child = ::fork();
    if (child < 0) return -2;
    if (child == 0) {
        set_num_threads(1);  // a forked child runs no OpenMP region (libgomp is not fork-safe)
        std::ifstream statm("/proc/self/statm");
        std::size_t pages = 0;
        statm >> pages;
        const auto used = pages * static_cast<std::size_t>(::sysconf(_SC_PAGESIZE));
        const rlimit limit{used + headroom, used + headroom};
        if (pages == 0 || ::setrlimit(RLIMIT_AS, &limit) != 0) ::_exit(static_cast<int>(Outcome::limit_failed));
        ::_exit(run());
    }
    int status = 0;
    if (::waitpid(child, &status, 0) != child || !WIFEXITED(status)) return -1;
    return WEXITSTATUS(status);
#endif
}

void expect_parse_error_in_little_memory(const std::function<void()>& read, const std::string& what) {
    EXPECT_EQ(outcome_with_little_memory(read), static_cast<int>(Outcome::parse_error))
        << what << " (0: ParseError, 1: no error, 2: bad_alloc, 3: another error, 4: setrlimit failed, -1: crash)";
}

const std::string su2_2d =
    "NDIME= 2\nNELEM= 2\n5 0 1 2\n5 0 2 3\nNPOIN= 4\n0 0\n1 0\n1 1\n0 1\n"
    "NMARK= 1\nMARKER_TAG= wall\nMARKER_ELEMS= 1\n3 0 1\n";

std::string replaced(std::string text, const std::string& from, const std::string& to) {
    const std::size_t at = text.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    return text.replace(at, from.size(), to);
}

const std::string msh_22 =
    "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n4\n1 0 0 0\n2 1 0 0\n3 0 1 0\n4 0 0 1\n$EndNodes\n"
    "$Elements\n2\n1 4 2 1 1 1 2 3 4\n2 2 2 5 2 1 3 2\n$EndElements\n";

const std::string msh_41 =
    "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n$Nodes\n1 4 1 4\n3 1 0 4\n1\n2\n3\n4\n"
    "0 0 0\n1 0 0\n0 1 0\n0 0 1\n$EndNodes\n$Elements\n1 1 1 1\n3 1 4 1\n1 1 2 3 4\n$EndElements\n";

std::vector<std::byte> small_plan_bytes() {
    const auto dir = test::scratch_dir();
    const test::BoxInBox m = test::box_in_box(2, 6);
    save_dg_idw_plan(dir / "small.plan", prepare_dg_idw(2, m.points, m.boundary));
    std::ifstream in(dir / "small.plan", std::ios::binary);
    const std::vector<char> chars{std::istreambuf_iterator<char>(in), {}};
    std::vector<std::byte> bytes(chars.size());
    std::memcpy(bytes.data(), chars.data(), chars.size());
    return bytes;
}

template <class T>
std::vector<std::byte> with_field(std::vector<std::byte> bytes, std::size_t offset, T value) {
    std::memcpy(bytes.data() + offset, &value, sizeof value);
    return bytes;
}

// Plan header offsets (plan_file.cpp): num_points at 20, the 7 array counts from 108, the arrays from 164.
constexpr std::size_t num_points_at = 20, counts_at = 108;  // plan_file.hpp: format version 3

}  // namespace

TEST(AbsurdCounts, HeaderClaimingTenToTheTwelveNodesFailsInLittleMemory) {
    const std::string huge = "1000000000000";
    const std::string su2 = replaced(su2_2d, "NPOIN= 4", "NPOIN= " + huge);
    expect_parse_error_in_little_memory([&] { read_su2_text("huge.su2", su2); }, "SU2 NPOIN= 10^12");
    try {
        read_su2_text("huge.su2", su2);
        FAIL() << "no error";
    } catch (const ParseError& e) {
        EXPECT_EQ(e.line(), 5u);  // the header line itself: nothing was read for it
        EXPECT_EQ(e.found(), huge);
    }
    expect_parse_error_in_little_memory([&] { read_gmsh_text("huge.msh", replaced(msh_22, "$Nodes\n4\n", "$Nodes\n" + huge + "\n")); },
                                        "Gmsh 2.2 $Nodes 10^12");
    expect_parse_error_in_little_memory(
        [&] { read_gmsh_text("huge.msh", replaced(msh_41, "1 4 1 4\n3 1 0 4\n", "1 " + huge + " 1 4\n3 1 0 " + huge + "\n")); },
        "Gmsh 4.1 $Nodes 10^12");
    const auto plan = small_plan_bytes();
    expect_parse_error_in_little_memory(
        [&] { load_dg_idw_plan_bytes(with_field<std::int64_t>(plan, num_points_at, 1'000'000'000'000), "huge.plan"); },
        "plan num_points 10^12");
    for (int array = 0; array < 7; ++array)
        expect_parse_error_in_little_memory(
            [&] {
                load_dg_idw_plan_bytes(with_field<std::uint64_t>(plan, counts_at + 8 * array, 1'000'000'000'000),
                                       "huge.plan");
            },
            "plan array " + std::to_string(array) + " of 10^12 elements");
}

TEST(AbsurdCounts, CountsTooLargeForTheFileFailInLittleMemory) {
    // 10^8 items: a reservation of a few GB that would succeed (untouched
    // pages cost nothing) yet is far more than a 100-byte file can hold.
    const std::string n = "100000000";
    for (const std::string key : {"NPOIN= 4", "NELEM= 2", "NMARK= 1", "MARKER_ELEMS= 1"}) {
        const std::string big = key.substr(0, key.find(' ') + 1) + n;
        expect_parse_error_in_little_memory([&] { read_su2_text("big.su2", replaced(su2_2d, key, big)); }, big);
    }
    expect_parse_error_in_little_memory([&] { read_gmsh_text("big.msh", replaced(msh_22, "$Nodes\n4\n", "$Nodes\n" + n + "\n")); },
                                        "Gmsh 2.2 $Nodes 10^8");
    expect_parse_error_in_little_memory(
        [&] { read_gmsh_text("big.msh", replaced(msh_22, "$Elements\n2\n", "$Elements\n" + n + "\n")); },
        "Gmsh 2.2 $Elements 10^8");
    expect_parse_error_in_little_memory(
        [&] { read_gmsh_text("big.msh", replaced(msh_41, "$Elements\n1 1 1 1\n3 1 4 1\n", "$Elements\n1 " + n + " 1 1\n3 1 4 " + n + "\n")); },
        "Gmsh 4.1 $Elements 10^8");
}

TEST(AbsurdCounts, NegativeCountsAreParseErrors) {
    expect_parse_error_in_little_memory([&] { read_su2_text("neg.su2", replaced(su2_2d, "NPOIN= 4", "NPOIN= -4")); },
                                        "SU2 NPOIN= -4");
    expect_parse_error_in_little_memory([&] { read_su2_text("neg.su2", replaced(su2_2d, "NELEM= 2", "NELEM= -1")); },
                                        "SU2 NELEM= -1");
    expect_parse_error_in_little_memory([&] { read_gmsh_text("neg.msh", replaced(msh_22, "$Nodes\n4\n", "$Nodes\n-4\n")); },
                                        "Gmsh $Nodes -4");
    expect_parse_error_in_little_memory(
        [&] { read_gmsh_text("neg.msh", replaced(msh_41, "1 1 1 1\n3 1 4 1\n", "1 1 1 1\n3 1 4 -1\n")); },
        "Gmsh 4.1 element block of -1");
    const auto plan = small_plan_bytes();
    expect_parse_error_in_little_memory(
        [&] { load_dg_idw_plan_bytes(with_field<std::int64_t>(plan, num_points_at, -1), "neg.plan"); },
        "plan num_points -1");
    // A count of 2^64 - 1 (-1 read as unsigned).
    expect_parse_error_in_little_memory(
        [&] { load_dg_idw_plan_bytes(with_field<std::int64_t>(plan, counts_at, -1), "neg.plan"); },
        "plan boundary count -1");
}

TEST(AbsurdCounts, AnElementNamingNodeTenToTheNineIsAParseError) {
    const std::string far = "1000000000";
    expect_parse_error_in_little_memory([&] { read_su2_text("far.su2", replaced(su2_2d, "5 0 2 3", "5 0 2 " + far)); },
                                        "SU2 cell node 10^9");
    expect_parse_error_in_little_memory([&] { read_su2_text("far.su2", replaced(su2_2d, "3 0 1", "3 0 " + far)); },
                                        "SU2 marker node 10^9");
    expect_parse_error_in_little_memory(
        [&] { read_gmsh_text("far.msh", replaced(msh_22, "1 4 2 1 1 1 2 3 4", "1 4 2 1 1 1 2 3 " + far)); },
        "Gmsh element node 10^9");
    // A node tag of 10^9 is legal (tags may be sparse) and costs one map entry.
    const Mesh sparse = read_gmsh_text("sparse.msh", replaced(replaced(msh_41, "\n4\n0 0 0", "\n" + far + "\n0 0 0"),
                                                              "1 1 2 3 4\n", "1 1 2 3 " + far + "\n"));
    EXPECT_EQ(sparse.num_points(), 4u);
    // A plan naming boundary node 10^9 (checksum made valid, so the index check is reached).
    const auto plan = small_plan_bytes();
    const auto far_node = fuzz::with_valid_plan_checksum(with_field<std::int32_t>(plan, 164, 1'000'000'000));
    try {
        load_dg_idw_plan_bytes(far_node, "far.plan");
        FAIL() << "no error";
    } catch (const ParseError& e) {
        EXPECT_NE(std::string(e.what()).find("a boundary node id in [0, "), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("byte offset 164"), std::string::npos) << e.what();
    }
}

TEST(AbsurdCounts, AMotionOfTenToTheTwelveStepsIsAParseError) {
    const auto dir = test::scratch_dir();
    const auto motion = [&](const std::string& steps) {
        return parse_motion_file(R"({"markers": {"wall": {"periodic": {"plunge": {"amplitude": [0, 1], "frequency": 1}}}},
                                     "time": {"time_step": 0.1, "steps": )" + steps + "}}",
                                 "steps.json", dir);
    };
    for (const char* steps : {"1e12", "1000000000000", "1000001", "9e15"})
        expect_parse_error_in_little_memory([&] { motion(steps); }, std::string("steps ") + steps);
    try {
        motion("1e12");
        FAIL() << "no error";
    } catch (const ParseError& e) {
        EXPECT_NE(e.expected().find("a number of steps from 1 to 1000000 at time.steps"), std::string::npos) << e.what();
    }
    // The largest accepted count is stored, not expanded into frames.
    const MotionSpec spec = motion("1000000");
    EXPECT_EQ(frame_count(spec), 1000000u);
    EXPECT_EQ(spec.frames.size(), 1u);
}
