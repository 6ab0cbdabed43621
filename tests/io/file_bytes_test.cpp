// FileBytes: a large file mapped, a small one read, both the file's bytes;
// the errors of read_file_text for what is not a readable regular file.
#include "dgwarp/io/file_bytes.hpp"

#include <gtest/gtest.h>

#include <fstream>
#include <sstream>
#include <string>

#include "dgwarp/core/error.hpp"
#include "dgwarp/io/su2/su2.hpp"
#include "dgwarp/io/text_reader.hpp"
#include "support/test_paths.hpp"

using namespace dgwarp;

namespace {

std::filesystem::path write_bytes(const std::filesystem::path& dir, const std::string& name, const std::string& bytes) {
    const auto file = dir / name;
    std::ofstream(file, std::ios::binary) << bytes;
    return file;
}

/// `n` bytes of varied text (lines of digits), so that a shifted or cut copy shows.
std::string varied_text(std::size_t n) {
    std::string s;
    s.reserve(n);
    for (std::size_t i = 0; s.size() < n; ++i) s += std::to_string(i * 7919 % 100003) + (i % 5 ? " " : "\n");
    s.resize(n);
    return s;
}

/// Kilobytes of the process's memory in the mapping that starts at `start`
/// (its Rss line in /proc/self/smaps); -1 when no mapping starts there.
long mapping_rss_kb(const void* start) {
    std::ifstream smaps("/proc/self/smaps");
    std::string line;
    bool in = false;
    while (std::getline(smaps, line)) {
        std::uintptr_t from = 0;
        if (std::istringstream head(line); line.find('-') != std::string::npos && (head >> std::hex >> from) &&
                                           line.find(':') > line.find('-')) {
            in = from == reinterpret_cast<std::uintptr_t>(start);
            continue;
        }
        if (in && line.rfind("Rss:", 0) == 0) return std::stol(line.substr(4));
    }
    return -1;
}

}  // namespace

TEST(FileBytes, ReleasedPagesLeaveMemoryAndTheBytesStayReadable) {
    const auto dir = test::scratch_dir();
    const std::string large = varied_text((std::size_t{8} << 20) + 777);
    FileBytes bytes = FileBytes::read(write_bytes(dir, "released.txt", large));
    ASSERT_TRUE(bytes.mapped());
    const void* start = bytes.view().data();
    const long all = mapping_rss_kb(start);
    EXPECT_GE(all, 8 * 1024 - 64);  // populated when mapped
    bytes.release_before(large.size() / 2);
    const long half = mapping_rss_kb(start);
    EXPECT_LE(half, all / 2 + 8);
    bytes.release_before(100);  // behind what is released: nothing
    EXPECT_EQ(mapping_rss_kb(start), half);
    bytes.release_before(large.size() + 4096);  // beyond the end: up to it
    EXPECT_LE(mapping_rss_kb(start), 4);
    // The bytes are the file's still (read again from the page cache).
    EXPECT_EQ(bytes.view(), large);
    // A string's bytes: nothing to release, nothing changes.
    FileBytes text(std::string("a string"));
    text.release_before(5);
    EXPECT_EQ(text.view(), "a string");
}

TEST(FileBytes, ALargeFileIsMappedASmallOneReadBothItsBytes) {
    const auto dir = test::scratch_dir();
    const std::string large = varied_text((std::size_t{1} << 20) + 12345);
    const std::string small = varied_text(1000);
    const FileBytes mapped = FileBytes::read(write_bytes(dir, "large.txt", large));
    EXPECT_TRUE(mapped.mapped());
    EXPECT_EQ(mapped.view(), large);
    const FileBytes read = FileBytes::read(write_bytes(dir, "small.txt", small));
    EXPECT_FALSE(read.mapped());
    EXPECT_EQ(read.view(), small);
    const FileBytes empty = FileBytes::read(write_bytes(dir, "empty.txt", ""));
    EXPECT_TRUE(empty.view().empty());
}

TEST(FileBytes, MovesKeepTheBytes) {
    const auto dir = test::scratch_dir();
    const std::string large = varied_text((std::size_t{1} << 20) + 1);
    FileBytes a = FileBytes::read(write_bytes(dir, "moved.txt", large));
    FileBytes b = std::move(a);
    EXPECT_EQ(b.view(), large);
    // A short string (kept inside the object itself) moved: the view follows it.
    FileBytes c(std::string("short"));
    FileBytes d = std::move(c);
    EXPECT_EQ(d.view(), "short");
    d = std::move(b);  // the mapping moves over a string
    EXPECT_TRUE(d.mapped());
    EXPECT_EQ(d.view(), large);
}

TEST(FileBytes, WhatIsNotAReadableRegularFileIsRefusedAsReadFileTextRefusesIt) {
    const auto dir = test::scratch_dir();
    for (const auto& path : {dir / "no-such-file.su2", dir, std::filesystem::path("/dev/zero")}) {
        std::string expected;
        try {
            (void)read_file_text(path);
            ADD_FAILURE() << "read_file_text read " << path;
        } catch (const IoError& e) {
            expected = e.what();
        }
        try {
            (void)FileBytes::read(path);
            ADD_FAILURE() << "FileBytes read " << path;
        } catch (const IoError& e) {
            EXPECT_EQ(e.what(), expected);
        }
    }
}

TEST(FileBytes, AMeshReadFromAMappedFileIsTheMeshReadFromItsText) {
    const auto dir = test::scratch_dir();
    // A strip of quadrilaterals long enough for its file to be mapped.
    std::string su2 = "NDIME= 2\nNELEM= 40000\n";
    for (int i = 0; i < 40000; ++i)
        su2 += "9 " + std::to_string(i) + " " + std::to_string(i + 1) + " " + std::to_string(40001 + i + 1) + " " +
               std::to_string(40001 + i) + "\n";
    su2 += "NPOIN= 80002\n";
    for (int row = 0; row < 2; ++row)
        for (int i = 0; i <= 40000; ++i) su2 += std::to_string(i * 0.001) + " " + std::to_string(row * 0.5) + "\n";
    su2 += "NMARK= 1\nMARKER_TAG= bottom\nMARKER_ELEMS= 1\n3 0 1\n";
    ASSERT_GT(su2.size(), std::size_t{1} << 20);
    const auto file = write_bytes(dir, "strip.su2", su2);
    ASSERT_TRUE(FileBytes::read(file).mapped());
    const Mesh from_file = read_su2(file);
    const Mesh from_text = read_su2_text("strip.su2", su2);
    EXPECT_EQ(from_file, from_text);
    EXPECT_EQ(from_file.num_points(), 80002u);
}
