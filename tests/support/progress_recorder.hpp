#pragma once
// Records the fractions a library call reports to a ProgressFn (from any
// thread) and checks them: in [0, 1], nondecreasing, ending at 1.
#include <gtest/gtest.h>

#include <mutex>
#include <vector>

#include "dgwarp/core/progress.hpp"

namespace dgwarp::test {

class ProgressRecorder {
public:
    /// A ProgressFn that appends each fraction under a mutex.
    ProgressFn fn() {
        return [this](double f) {
            std::lock_guard lock(mutex_);
            fractions_.push_back(f);
        };
    }
    const std::vector<double>& fractions() const { return fractions_; }

    /// Checks the fractions: at least `min_calls` of them, each in [0, 1],
    /// nondecreasing, the last one 1.
    void expect_complete(std::size_t min_calls) const {
        ASSERT_GE(fractions_.size(), min_calls);
        for (std::size_t i = 0; i < fractions_.size(); ++i) {
            EXPECT_GE(fractions_[i], 0.0) << "call " << i;
            EXPECT_LE(fractions_[i], 1.0) << "call " << i;
            if (i > 0) {
                EXPECT_GE(fractions_[i], fractions_[i - 1]) << "call " << i;
            }
        }
        EXPECT_EQ(fractions_.back(), 1.0);
    }

private:
    std::mutex mutex_;
    std::vector<double> fractions_;
};

}  // namespace dgwarp::test
