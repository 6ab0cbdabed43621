#include "dgwarp/methods/rotation_series.hpp"

#include <gtest/gtest.h>

#include <cmath>

using namespace dgwarp;

TEST(DgIdwRotationFactors, MatchSinAndCosWithinAFewUlp) {
    // The Taylor branch (theta <= 1) against the closed forms, where those are accurate.
    for (double theta = 1e-3; theta <= 3.0; theta += 1e-3) {
        const RotationFactors r = rotation_factors(theta * theta);
        EXPECT_NEAR(r.f, std::sin(theta) / theta, 4e-16) << theta;
        EXPECT_NEAR(r.g, 2 * std::pow(std::sin(theta / 2) / theta, 2), 4e-16) << theta;
    }
    const RotationFactors zero = rotation_factors(0);
    EXPECT_EQ(zero.f, 1.0);
    EXPECT_EQ(zero.g, 0.5);
}
