#include "dgwarp/core/parallel_for.hpp"

#include <gtest/gtest.h>

#include <atomic>
#include <stdexcept>
#include <vector>

using namespace dgwarp;

namespace {
// Restores the thread count a test changed.
struct ThreadCount {
    int saved = num_threads();
    ~ThreadCount() { set_num_threads(saved); }
};
}  // namespace

TEST(ParallelFor, VisitsEveryIndexOnceShortAndLongLoops) {
    ThreadCount keep;
    set_num_threads(2);
    for (std::int64_t n : {std::int64_t{0}, std::int64_t{1}, parallel_grain - 1, parallel_grain * 3 + 7}) {
        std::vector<int> hits(static_cast<std::size_t>(n), 0);
        parallel_for(n, [&](std::int64_t i) { ++hits[static_cast<std::size_t>(i)]; });
        for (int h : hits) ASSERT_EQ(h, 1) << "n = " << n;
    }
}

TEST(ParallelFor, ChunksCoverTheRangeContiguouslyAndUseTheThreads) {
    ThreadCount keep;
    set_num_threads(2);
    for (std::int64_t n : {std::int64_t{1}, std::int64_t{100}, parallel_grain * 4}) {
        std::vector<int> hits(static_cast<std::size_t>(n), 0);
        std::atomic<int> chunks{0};
        parallel_for_chunks(n, [&](std::int64_t begin, std::int64_t end) {
            ++chunks;
            for (std::int64_t i = begin; i < end; ++i) ++hits[static_cast<std::size_t>(i)];
        });
        for (int h : hits) ASSERT_EQ(h, 1) << "n = " << n;
        EXPECT_EQ(chunks.load(), n < parallel_grain ? 1 : 2) << "n = " << n;
    }
}

TEST(ParallelFor, RethrowsTheBodysException) {
    ThreadCount keep;
    set_num_threads(2);
    for (std::int64_t n : {std::int64_t{10}, parallel_grain * 2}) {
        EXPECT_THROW(parallel_for(n, [&](std::int64_t i) {
                         if (i == n / 2) throw std::runtime_error("bad index");
                     }),
                     std::runtime_error);
    }
}
