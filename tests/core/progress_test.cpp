// ProgressCounter and progress_part: the pieces every long call reports through.
#include "dgwarp/core/progress.hpp"

#include <gtest/gtest.h>

#include "dgwarp/core/parallel_for.hpp"
#include "support/progress_recorder.hpp"

using namespace dgwarp;

TEST(Progress, CounterReportsStartPercentStepsAndEnd) {
    test::ProgressRecorder rec;
    const ProgressFn fn = rec.fn();
    {
        ProgressCounter counter(fn, 1000);
        for (int i = 0; i < 1000; ++i) counter.add(1);
        counter.finish();
    }
    rec.expect_complete(100);
    EXPECT_EQ(rec.fractions().front(), 0.0);
    EXPECT_LE(rec.fractions().size(), 102u);  // about once per percent, not per item
}

TEST(Progress, CounterFromManyThreadsStaysOrdered) {
    const int threads = num_threads();
    set_num_threads(4);
    test::ProgressRecorder rec;
    const ProgressFn fn = rec.fn();
    const std::int64_t n = 200000;
    ProgressCounter counter(fn, n);
    parallel_for(n, [&](std::int64_t) { counter.add(1); });
    set_num_threads(threads);
    rec.expect_complete(50);
}

TEST(Progress, EmptyFunctionReportsNothingAndFinishReportsOnce) {
    const ProgressFn none;
    ProgressCounter quiet(none, 10);
    quiet.add(10);
    quiet.finish();  // must not call an empty function

    test::ProgressRecorder rec;
    const ProgressFn fn = rec.fn();
    ProgressCounter empty(fn, 0);  // nothing to count: 0, then 1 from finish
    empty.finish();
    empty.finish();
    EXPECT_EQ(rec.fractions(), (std::vector<double>{0.0, 1.0}));
}

TEST(Progress, PartMapsIntoItsRange) {
    test::ProgressRecorder rec;
    const ProgressFn part = progress_part(rec.fn(), 0.4, 0.9);
    part(0);
    part(0.5);
    part(1);
    ASSERT_EQ(rec.fractions().size(), 3u);
    EXPECT_DOUBLE_EQ(rec.fractions()[0], 0.4);
    EXPECT_DOUBLE_EQ(rec.fractions()[1], 0.65);
    EXPECT_DOUBLE_EQ(rec.fractions()[2], 0.9);
    EXPECT_FALSE(progress_part({}, 0, 1));
}
