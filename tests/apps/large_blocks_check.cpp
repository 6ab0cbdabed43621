// The command's operator new (apps/dgwarp/large_blocks.cpp), in a program of
// its own since it replaces the program's allocation: large blocks come
// 2 MiB-aligned and advised as huge-page memory, small
// ones from malloc, and every kind of delete gives each back where it came from.
#include <gtest/gtest.h>

#include <cstdint>
#include <fstream>
#include <memory>
#include <new>
#include <numeric>
#include <sstream>
#include <string>
#include <vector>

#include "large_blocks.hpp"

// Under the sanitizers the program keeps their operator new (large_blocks.cpp
// compiles to nothing there), so there is nothing of ours to check.
#if DGWARP_LARGE_BLOCKS
#define SKIP_UNDER_SANITIZERS() (void)0
#else
#define SKIP_UNDER_SANITIZERS() GTEST_SKIP() << "a sanitizer's operator new is in use"
#endif

namespace {

constexpr std::uintptr_t huge_page = std::uintptr_t{2} << 20;

std::uintptr_t address(const void* p) { return reinterpret_cast<std::uintptr_t>(p); }

/// The THPeligible line of /proc/self/smaps for the mapping holding p: 1 when
/// the kernel may back it with huge pages; -1 when there is no such line.
int thp_eligible(const void* p) {
    std::ifstream smaps("/proc/self/smaps");
    std::string line;
    bool inside = false;
    while (std::getline(smaps, line)) {
        std::uintptr_t from = 0, to = 0;
        char dash = 0;
        std::istringstream head(line);
        if (head >> std::hex >> from >> dash >> to && dash == '-') {
            inside = from <= address(p) && address(p) < to;
            continue;
        }
        if (inside && line.rfind("THPeligible:", 0) == 0) return std::stoi(line.substr(12));
    }
    return -1;
}

bool huge_pages_possible() {
    std::ifstream f("/sys/kernel/mm/transparent_hugepage/enabled");
    std::string s;
    std::getline(f, s);
    return !s.empty() && s.find("[never]") == std::string::npos;
}

}  // namespace

TEST(LargeBlocks, ALargeArrayIsAlignedAdvisedAndHoldsItsValues) {
    SKIP_UNDER_SANITIZERS();
    std::vector<double> v(3'000'000);  // 24 MB
    EXPECT_EQ(address(v.data()) % huge_page, 0u);
    std::iota(v.begin(), v.end(), 0.5);
    EXPECT_EQ(v[2'999'999], 2'999'999.5);
    if (huge_pages_possible()) {
        EXPECT_EQ(thp_eligible(v.data()), 1);
    }
    v.resize(5'000'000);  // a larger block, the values copied over
    EXPECT_EQ(v[2'999'999], 2'999'999.5);
    EXPECT_EQ(address(v.data()) % huge_page, 0u);
    // From 2 MiB on: an array of one id per node of a large mesh.
    std::vector<std::int32_t> ids(std::size_t{1} << 19);
    EXPECT_EQ(address(ids.data()) % huge_page, 0u);
}

TEST(LargeBlocks, SmallBlocksComeFromMallocAndEveryDeleteFitsItsNew) {
    SKIP_UNDER_SANITIZERS();
    std::vector<std::unique_ptr<char[]>> small;
    for (int i = 0; i < 10000; ++i) small.emplace_back(new char[static_cast<std::size_t>(i % 977 + 1)]);
    small.clear();
    auto* one = new std::uint64_t[(std::size_t{9} << 20) / 8];
    one[0] = 1;
    delete[] one;
    auto* nothrow = new (std::nothrow) char[std::size_t{9} << 20];
    ASSERT_NE(nothrow, nullptr);
    nothrow[(std::size_t{9} << 20) - 1] = 'x';
    ::operator delete[](nothrow, std::nothrow);
    void* sized = ::operator new(std::size_t{10} << 20);
    ::operator delete(sized, std::size_t{10} << 20);
}

TEST(LargeBlocks, MoreLargeBlocksThanTheTableHoldsFallBackToMalloc) {
    SKIP_UNDER_SANITIZERS();
    // 1,100 blocks of 8 MiB alive at once (virtual memory only: never
    // touched); those past the table's 1,024 come from malloc.
    std::vector<char*> blocks;
    for (int i = 0; i < 1100; ++i) blocks.push_back(new char[std::size_t{8} << 20]);
    int aligned = 0;
    for (char* b : blocks) aligned += address(b) % huge_page == 0 ? 1 : 0;
    EXPECT_GE(aligned, 1000);
    EXPECT_LT(aligned, 1100);
    for (char* b : blocks) delete[] b;
    // The table's slots are free again.
    std::vector<double> v(2'000'000);
    EXPECT_EQ(address(v.data()) % huge_page, 0u);
}

TEST(LargeBlocks, AnAllocationBeyondMemoryThrowsBadAlloc) {
    SKIP_UNDER_SANITIZERS();
    EXPECT_THROW((void)::operator new(std::size_t{1} << 62), std::bad_alloc);
    EXPECT_EQ(::operator new(std::size_t{1} << 62, std::nothrow), nullptr);
}
