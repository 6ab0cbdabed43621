#include "dgwarp/methods/rotation_series.hpp"

#include <gtest/gtest.h>

#include <cmath>

using namespace dgwarp;

namespace {
double exact_f(double theta) { return std::sin(theta) / theta; }
double exact_g(double theta) { return 2 * std::pow(std::sin(theta / 2) / theta, 2); }  // no cancellation
}  // namespace

TEST(DgIdwRotationFactors, MatchSinAndCosWithinAFewUlp) {
    for (double theta = 1e-3; theta <= 3.0; theta += 1e-3) {
        const RotationFactors r = rotation_factors(theta * theta);
        EXPECT_NEAR(r.f, exact_f(theta), 4e-16) << theta;
        EXPECT_NEAR(r.g, exact_g(theta), 4e-16) << theta;
    }
    const RotationFactors zero = rotation_factors(0);
    EXPECT_EQ(zero.f, 1.0);
    EXPECT_EQ(zero.g, 0.5);
}

TEST(DgIdwRotationFactors, ShortSeriesAreAccurateUpToTheirLimits) {
    auto check = [](auto series, int terms) {
        const double limit = taylor_angle2_limit(terms);
        for (int i = 1; i <= 1000; ++i) {
            const double angle2 = limit * i / 1000, theta = std::sqrt(angle2);
            const RotationFactors r = series(angle2);
            EXPECT_NEAR(r.f, exact_f(theta), 3e-16) << terms << " terms, theta " << theta;
            EXPECT_NEAR(r.g, exact_g(theta), 3e-16) << terms << " terms, theta " << theta;
        }
    };
    check(rotation_factors_series<4>, 4);
    check(rotation_factors_series<6>, 6);
    check(rotation_factors_series<8>, 8);
    check(rotation_factors_series<10>, 10);
    // The limits are not loose: two terms fewer are not enough at the next limit.
    EXPECT_GT(std::abs(rotation_factors_series<4>(taylor_angle2_limit(6)).f - exact_f(std::sqrt(taylor_angle2_limit(6)))),
              1e-15);
}
