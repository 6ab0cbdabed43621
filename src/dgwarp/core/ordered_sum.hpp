#pragma once
// A compensated (Neumaier) sum in the order the values are added:
// deterministic, and accurate to about one rounding whatever the count (the
// quality summaries' means; under mpirun, each process's part of them).
#include <cmath>

namespace dgwarp {

class OrderedSum {
public:
    void add(double v) {
        const double t = sum_ + v;
        compensation_ += std::fabs(sum_) >= std::fabs(v) ? (sum_ - t) + v : (v - t) + sum_;
        sum_ = t;
    }
    double value() const { return sum_ + compensation_; }

private:
    double sum_ = 0, compensation_ = 0;
};

}  // namespace dgwarp
