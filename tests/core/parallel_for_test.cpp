#include "dgwarp/core/parallel_for.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <mutex>
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

TEST(ParallelFor, BlocksCoverTheRangeOnceInBlocksOfTheGivenSize) {
    ThreadCount keep;
    for (int threads : {1, 2}) {
        set_num_threads(threads);
        for (std::int64_t n : {std::int64_t{0}, std::int64_t{1}, std::int64_t{999}, std::int64_t{1000}, std::int64_t{12345}}) {
            std::vector<int> hits(static_cast<std::size_t>(n), 0);
            std::vector<std::pair<std::int64_t, std::int64_t>> blocks;
            std::mutex m;
            parallel_for_blocks(n, 1000, [&](std::int64_t begin, std::int64_t end) {
                {
                    std::lock_guard lock(m);
                    blocks.emplace_back(begin, end);
                }
                for (std::int64_t i = begin; i < end; ++i) ++hits[static_cast<std::size_t>(i)];
            });
            for (int h : hits) ASSERT_EQ(h, 1) << "n = " << n;
            std::sort(blocks.begin(), blocks.end());
            if (threads == 1 || n <= 1000) {
                EXPECT_EQ(blocks.size(), n == 0 ? 0u : 1u) << "n = " << n;  // one call on the caller
            } else {
                EXPECT_EQ(blocks.size(), static_cast<std::size_t>((n + 999) / 1000)) << "n = " << n;
                for (std::size_t b = 0; b < blocks.size(); ++b)
                    EXPECT_EQ(blocks[b].first, static_cast<std::int64_t>(b) * 1000);
            }
        }
    }
    set_num_threads(2);
    EXPECT_THROW(parallel_for_blocks(5000, 100, [](std::int64_t begin, std::int64_t) {
                     if (begin == 2500) throw std::runtime_error("bad block");
                 }),
                 std::runtime_error);
}

TEST(ParallelFor, ThreadCountsAreClampedToWhatOpenMpCanStart) {
    ThreadCount keep;
    EXPECT_GE(max_threads(), 64);
    set_num_threads(100000);  // OpenMP crashed starting this many (issue #17)
    EXPECT_EQ(num_threads(), max_threads());
    std::vector<int> hits(static_cast<std::size_t>(parallel_grain * 2), 0);
    parallel_for(parallel_grain * 2, [&](std::int64_t i) { ++hits[static_cast<std::size_t>(i)]; });
    EXPECT_TRUE(std::all_of(hits.begin(), hits.end(), [](int h) { return h == 1; }));
    set_num_threads(0);
    EXPECT_EQ(num_threads(), 1);
    set_num_threads(-5);
    EXPECT_EQ(num_threads(), 1);
}

TEST(ParallelFor, RunConcurrentlyUsesTwoThreadsAndOneWhenThatIsAll) {
    ThreadCount keep;
    for (int threads : {1, 2}) {
        set_num_threads(threads);
        std::thread::id a_id, b_id;
        std::vector<char> order;
        std::mutex m;
        std::atomic<bool> a_started{false};
        run_concurrently(
            [&] {
                a_started = true;
                a_id = std::this_thread::get_id();
                std::lock_guard lock(m);
                order.push_back('a');
            },
            [&] {
                // With two threads b waits until a runs beside it (a timeout
                // keeps a broken run_concurrently from hanging the test).
                for (int k = 0; threads == 2 && !a_started && k < 2000; ++k)
                    std::this_thread::sleep_for(std::chrono::milliseconds(1));
                b_id = std::this_thread::get_id();
                std::lock_guard lock(m);
                order.push_back('b');
            });
        ASSERT_EQ(order.size(), 2u);
        if (threads == 1) {
            EXPECT_EQ(a_id, b_id);
            EXPECT_EQ(order, (std::vector<char>{'a', 'b'}));  // a first
        } else {
            EXPECT_NE(a_id, b_id);
        }
        // A parallel_for inside either runs on its own thread alone, and still visits every index.
        std::vector<int> hits(static_cast<std::size_t>(parallel_grain * 2), 0);
        run_concurrently([&] { parallel_for(parallel_grain, [&](std::int64_t i) { ++hits[i]; }); },
                         [&] { parallel_for(parallel_grain, [&](std::int64_t i) { ++hits[parallel_grain + i]; }); });
        for (int h : hits) ASSERT_EQ(h, 1);
    }
}

namespace {

/// `run(a, b)` (run_concurrently, run_beside) finishes b when a throws,
/// rethrows a's error first, and b's when only b throws.
template <class Run>
void expect_both_run_and_the_first_error_is_rethrown(Run&& run, int threads) {
    bool b_done = false;
    try {
        run([] { throw std::runtime_error("a"); },
            [&] {
                b_done = true;
                throw std::logic_error("b");
            });
        ADD_FAILURE() << "no exception";
    } catch (const std::runtime_error& e) {
        EXPECT_STREQ(e.what(), "a");
    }
    EXPECT_TRUE(b_done) << threads << " thread(s)";
    EXPECT_THROW(run([] {}, [] { throw std::logic_error("b"); }), std::logic_error);
}

}  // namespace

TEST(ParallelFor, RunConcurrentlyFinishesBothAndRethrowsTheFirstTasksError) {
    ThreadCount keep;
    for (int threads : {1, 2}) {
        set_num_threads(threads);
        expect_both_run_and_the_first_error_is_rethrown(
            [](auto&& a, auto&& b) { run_concurrently(a, b); }, threads);
    }
}

TEST(ParallelFor, RunBesideKeepsEveryThreadHereAndOneBesideAndRethrowsTheFirstTasksError) {
    ThreadCount keep;
    for (int threads : {1, 3}) {
        set_num_threads(threads);
        std::thread::id here = std::this_thread::get_id(), a_id, b_id;
        int a_threads = 0, b_threads = 0;
        std::atomic<bool> a_started{false};
        std::vector<int> hits(static_cast<std::size_t>(parallel_grain * 4), 0);
        run_beside(
            [&] {
                a_started = true;
                a_id = std::this_thread::get_id();
                a_threads = num_threads();
                parallel_for(parallel_grain * 2, [&](std::int64_t i) { ++hits[i]; });
            },
            [&] {
                for (int k = 0; threads > 1 && !a_started && k < 2000; ++k)
                    std::this_thread::sleep_for(std::chrono::milliseconds(1));
                b_id = std::this_thread::get_id();
                b_threads = num_threads();
                parallel_for(parallel_grain * 2, [&](std::int64_t i) { ++hits[parallel_grain * 2 + i]; });
            });
        for (int h : hits) ASSERT_EQ(h, 1);
        EXPECT_EQ(a_id, here);
        EXPECT_EQ(a_threads, threads);
        EXPECT_EQ(b_threads, 1);
        if (threads == 1) EXPECT_EQ(b_id, here);
        else EXPECT_NE(b_id, here);
        EXPECT_EQ(num_threads(), threads);  // the setting here is as it was
        expect_both_run_and_the_first_error_is_rethrown([](auto&& a, auto&& b) { run_beside(a, b); }, threads);
    }
}

TEST(ParallelForOrdered, InOrderCallsComeInIndexOrderOnTheThreadThatRanTheBody) {
    ThreadCount keep;
    struct State {
        std::thread::id owner = std::this_thread::get_id();
        std::int64_t made = -1;  // the index body last filled this state for
    };
    for (int threads : {1, 2, 3, 7}) {
        set_num_threads(threads);
        const std::int64_t n = 500;
        std::vector<std::int64_t> order;
        std::vector<std::thread::id> ran_on;
        std::atomic<int> bodies{0};
        parallel_for_ordered<State>(
            n,
            [&](std::int64_t i, State& s) {
                EXPECT_EQ(s.owner, std::this_thread::get_id());  // each thread's own state
                s.made = i;
                ++bodies;
            },
            [&](std::int64_t i, const State& s) {
                EXPECT_EQ(s.made, i) << threads;  // the state body filled for this index
                EXPECT_EQ(s.owner, std::this_thread::get_id());
                order.push_back(i);  // no lock: in_order calls never overlap
                ran_on.push_back(std::this_thread::get_id());
            });
        EXPECT_EQ(bodies.load(), n);
        std::vector<std::int64_t> expected(static_cast<std::size_t>(n));
        for (std::int64_t i = 0; i < n; ++i) expected[static_cast<std::size_t>(i)] = i;
        EXPECT_EQ(order, expected) << threads;
        std::sort(ran_on.begin(), ran_on.end());
        const auto used = std::unique(ran_on.begin(), ran_on.end()) - ran_on.begin();
        EXPECT_EQ(used, threads) << "every thread takes part";  // round-robin, 500 indices
    }
}

TEST(ParallelForOrdered, TheFirstErrorIsRethrownAndNothingIsConsumedAfterIt) {
    ThreadCount keep;
    for (int threads : {1, 2, 3}) {
        set_num_threads(threads);
        for (bool in_body : {true, false}) {
            std::vector<std::int64_t> consumed;
            try {
                parallel_for_ordered<int>(
                    200,
                    [&](std::int64_t i, int&) {
                        if (in_body && i == 57) throw std::runtime_error("body 57");
                    },
                    [&](std::int64_t i, int&) {
                        if (!in_body && i == 57) throw std::runtime_error("in order 57");
                        consumed.push_back(i);
                    });
                ADD_FAILURE() << "no error";
            } catch (const std::runtime_error& e) {
                EXPECT_STREQ(e.what(), in_body ? "body 57" : "in order 57");
            }
            // Every index before the failing one, none after it.
            ASSERT_LE(consumed.size(), 57u) << threads;
            for (std::size_t k = 0; k < consumed.size(); ++k) EXPECT_EQ(consumed[k], static_cast<std::int64_t>(k));
            if (!in_body) {
                EXPECT_EQ(consumed.size(), 57u);
            }
        }
    }
}
