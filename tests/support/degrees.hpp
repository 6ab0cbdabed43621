#pragma once
// One degree in radians, for tests that write their angles in degrees.
#include <numbers>

namespace dgwarp::test {

inline constexpr double deg = std::numbers::pi / 180;

}  // namespace dgwarp::test
