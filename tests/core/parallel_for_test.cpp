#include "dgwarp/core/parallel_for.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <stdexcept>
#include <thread>
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

TEST(ParallelFor, ShortLoopsStayOnTheCallerUnlessTheGrainIsOne) {
    ThreadCount keep;
    set_num_threads(2);
    if (num_threads() < 2) GTEST_SKIP() << "built without OpenMP";
    auto threads_used = [](std::int64_t grain) {
        std::vector<std::thread::id> ids(8);
        parallel_for(8, [&](std::int64_t i) { ids[static_cast<std::size_t>(i)] = std::this_thread::get_id(); }, grain);
        std::sort(ids.begin(), ids.end());
        return std::unique(ids.begin(), ids.end()) - ids.begin();
    };
    EXPECT_EQ(threads_used(parallel_grain), 1);  // 8 cheap indices: not worth a thread
    EXPECT_EQ(threads_used(1), 2);               // 8 blocks of real work (the graph's location)
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
