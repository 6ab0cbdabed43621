#include "dgwarp/methods/dg_idw_step.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cstring>
#include <set>
#include <vector>

#include "dgwarp/methods/rotation_series.hpp"
#include "support/box_in_box.hpp"

using namespace dgwarp;
using dgwarp::test::box_in_box;
using dgwarp::test::BoxInBox;
using dgwarp::test::jittered;
using dgwarp::test::random_motion;

namespace {

// A jittered box in a box whose boundary nodes move or not in a mixed pattern
// (a third of them flipped), so that graph simplices have 0 to 4 moving corners.
BoxInBox mixed_box() {
    BoxInBox m = jittered(box_in_box(3, 10), 0.01, 7);
    for (std::size_t b = 0; b < m.boundary.moving.size(); b += 3) m.boundary.moving[b] ^= 1;
    return m;
}

// How many graph simplices holding a volume node have 0, 1, .., 4 moving corners.
std::array<int, 5> moving_corner_histogram(const DgIdwPlan& plan) {
    std::array<int, 5> h{};
    for (std::size_t s = 0; s < plan.simplex_motion.size(); s += 4) {
        int moving = 0;
        for (int k = 0; k < 4; ++k) moving += plan.simplex_motion[s + k] >= 0;
        ++h[moving];
    }
    return h;
}

}  // namespace

// The step's AVX2 copy (taken where the processor has AVX2) sums the corners'
// motions four components at a time, the SSE2 copy two at a time: both must
// give the bits of the other, for every number of Taylor terms the rotation
// bound picks (translation only, 4, 6, 8, 10 terms and beyond 1 rad), both
// weightings and simplices with 0 to 4 moving corners. A reordered sum or a
// fused multiply-add in either copy changes last bits and fails this test.
TEST(DgIdwStep, Avx2KernelGivesTheSameBitsAsSse2) {
    if (!cpu_has_avx2()) GTEST_SKIP() << "no AVX2 on this processor: both kernels are the SSE2 one";
    const BoxInBox m = mixed_box();
    std::set<int> lengths;  // the Taylor lengths the motions below reach (11: beyond 1 rad, std::sin/cos)
    for (DgIdwWeighting weighting : {DgIdwWeighting::paper, DgIdwWeighting::continuous}) {
        DgIdwOptions options;
        options.weighting = weighting;
        const DgIdwPlan plan = prepare_dg_idw(3, m.points, m.boundary, options);
        const std::array<int, 5> h = moving_corner_histogram(plan);
        for (int moving = 0; moving <= 4; ++moving) EXPECT_GT(h[moving], 0) << moving << " moving corners";
        for (double amount : {0.0, 0.004, 0.03, 0.08, 0.15, 0.4}) {
            BoundaryMotion motion = random_motion(m, 11, amount > 0 ? amount : 0.05);
            if (amount == 0)
                for (NodeMotion& nm : motion) nm.rotation = {};
            const double angle2 = max_rotation_angle2(plan, motion);
            lengths.insert(angle2 == 0 ? 0
                           : angle2 <= taylor_angle2_limit(4) ? 4
                           : angle2 <= taylor_angle2_limit(6) ? 6
                           : angle2 <= taylor_angle2_limit(8) ? 8
                           : angle2 <= taylor_angle2_limit(10) ? 10
                                                              : 11);
            std::vector<double> avx(m.points.size()), sse(m.points.size());
            deform_dg_idw_bounded(plan, m.points, motion, avx, angle2, StepKernel::automatic);
            deform_dg_idw_bounded(plan, m.points, motion, sse, angle2, StepKernel::baseline);
            EXPECT_EQ(0, std::memcmp(avx.data(), sse.data(), avx.size() * sizeof(double)))
                << weighting_name(weighting) << ", motion amount " << amount << ", max angle^2 " << angle2;
            EXPECT_NE(0, std::memcmp(sse.data(), m.points.data(), sse.size() * sizeof(double)));  // it moved
        }
    }
    EXPECT_EQ(lengths, (std::set<int>{0, 4, 6, 8, 10, 11}));
}
