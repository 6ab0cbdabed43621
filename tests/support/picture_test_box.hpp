#pragma once
// The rect-box the picture tests were written for: the rectangle
// [-1, 1] × [-0.5, 0.5] in the box [-6, 6]².
#include "dgwarp/cases/rect_box.hpp"

namespace dgwarp::test {

inline const RectBoxOptions picture_test_box{2.0, 1.0, 6.0, 78, 30, 1.12};

}  // namespace dgwarp::test
