// Replays, through the fuzz targets' own checks (fuzz/fuzz_checks.hpp), every
// input in tests/data/fuzz_regressions/<target>/: inputs the fuzzers crashed
// on (named crash-*, leak-*, oom-*, timeout-* as libFuzzer saved them, before
// the fix) and hand-made hostile ones. Each must give a clean dgwarp::Error
// or a valid result. The seed corpora fuzz/corpus/<target>/ are replayed too:
// they are valid files, so they must be read without error.
#include <gtest/gtest.h>

#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "dgwarp/core/error.hpp"
#include "fuzz_checks.hpp"
#include "support/test_paths.hpp"

using namespace dgwarp;

namespace {

using Check = void (*)(std::span<const std::uint8_t>);

std::vector<std::uint8_t> read_bytes(const std::filesystem::path& p) {
    std::ifstream in(p, std::ios::binary);
    const std::vector<char> chars{std::istreambuf_iterator<char>(in), {}};
    return {chars.begin(), chars.end()};
}

std::vector<std::filesystem::path> files_in(const std::filesystem::path& dir) {
    std::vector<std::filesystem::path> files;
    for (const auto& e : std::filesystem::directory_iterator(dir))
        if (e.is_regular_file()) files.push_back(e.path());
    std::sort(files.begin(), files.end());
    return files;
}

/// Runs `check` on every file of `dir`; returns how many gave a dgwarp::Error.
/// Any other exception fails the test (a crash ends it).
std::size_t replay(const std::filesystem::path& dir, Check check) {
    const auto files = files_in(dir);
    EXPECT_FALSE(files.empty()) << dir;
    std::size_t errors = 0;
    for (const auto& file : files) {
        const std::vector<std::uint8_t> bytes = read_bytes(file);
        try {
            check(bytes);
        } catch (const Error&) {
            ++errors;
        } catch (const std::exception& e) {
            ADD_FAILURE() << file << ": " << e.what();
        }
    }
    return errors;
}

std::filesystem::path regressions(const char* target) {
    return test::source_dir() / "tests" / "data" / "fuzz_regressions" / target;
}
std::filesystem::path seeds(const char* target) { return test::source_dir() / "fuzz" / "corpus" / target; }

}  // namespace

TEST(FuzzRegression, Su2) {
    replay(regressions("su2"), fuzz::check_su2);
    EXPECT_EQ(replay(seeds("su2"), fuzz::check_su2), 0u);
}

TEST(FuzzRegression, Gmsh) {
    replay(regressions("gmsh"), fuzz::check_gmsh);
    EXPECT_EQ(replay(seeds("gmsh"), fuzz::check_gmsh), 0u);
}

TEST(FuzzRegression, Vtu) {
    // Every seed (dgwarp's and meshio's writers: binary, ascii, zlib) is read
    // and survives write_vtu then read_vtu_text.
    EXPECT_EQ(replay(seeds("vtu"), fuzz::check_vtu), 0u);
}

TEST(FuzzRegression, OpenFoam) {
    // Every hand-made hostile input fails cleanly; every seed is read.
    const std::size_t hostile = files_in(regressions("openfoam")).size();
    EXPECT_EQ(replay(regressions("openfoam"), fuzz::check_openfoam), hostile);
    EXPECT_EQ(replay(seeds("openfoam"), fuzz::check_openfoam), 0u);
}

TEST(FuzzRegression, Cgns) {
    // Every input fails cleanly (hand-made: a structured zone, truncated HDF5
    // and ADF files) but those named readable-*, files dgwarp reads whose
    // mesh the fuzz check writes and reads back (a marker name the writer
    // refuses); every seed is read.
    std::size_t hostile = 0;
    for (const auto& file : files_in(regressions("cgns"))) hostile += file.filename().string().rfind("readable-", 0) != 0;
    EXPECT_EQ(replay(regressions("cgns"), fuzz::check_cgns), hostile);
    EXPECT_EQ(replay(seeds("cgns"), fuzz::check_cgns), 0u);
}

TEST(FuzzRegression, Motion) {
    replay(regressions("motion"), fuzz::check_motion);
    // Seeds that name a CSV or SU2 file fail with an IoError: the fuzz target's
    // base folder is empty on purpose. Every other seed is read.
    std::size_t naming_files = 0;
    for (const auto& file : files_in(seeds("motion"))) {
        const std::vector<std::uint8_t> bytes = read_bytes(file);
        const std::string text(bytes.begin(), bytes.end());
        naming_files += text.find("_file\"") != std::string::npos;
    }
    EXPECT_EQ(replay(seeds("motion"), fuzz::check_motion), naming_files);
}

TEST(FuzzRegression, Plan) {
    replay(regressions("plan"), fuzz::check_plan);
    EXPECT_EQ(replay(seeds("plan"), fuzz::check_plan), 0u);
}
