#include "dgwarp/methods/dg_harmonic_step.hpp"

#include <gtest/gtest.h>

#include <cstring>
#include <vector>

#include "dgwarp/core/parallel_for.hpp"
#include "support/box_in_box.hpp"

using namespace dgwarp;
using dgwarp::test::box_in_box;
using dgwarp::test::BoxInBox;
using dgwarp::test::jittered;
using dgwarp::test::random_motion;

// DG-harmonic's per-node pass has an AVX2 copy (four values at a time) and
// an SSE2 one (two at a time): both must give the other's bits, in 2D and 3D,
// with and without rotation. A reordered sum or a fused multiply-add in either
// copy fails this test.
TEST(DgHarmonicStep, Avx2KernelGivesTheSameBitsAsSse2) {
    if (!cpu_has_avx2()) GTEST_SKIP() << "no AVX2 on this processor: both kernels are the SSE2 one";
    for (int dim : {2, 3}) {
        const BoxInBox m = jittered(box_in_box(dim, dim == 2 ? 24 : 10), 0.02, 7);
        // A denser coarse level than the default, so that these small boxes have coarse interior points.
        const DgHarmonicPlan plan = prepare_dg_harmonic(dim, m.points, m.boundary, {.wall_spacing = 2.0, .growth = 0.5});
        ASSERT_GT(plan.stats.coarse_interior, 0);
        for (bool rotates : {false, true}) {
            BoundaryMotion motion = random_motion(m, 5, 0.1);
            if (!rotates)
                for (NodeMotion& nm : motion) nm.rotation = {};
            std::vector<double> avx(m.points.size()), sse(m.points.size());
            deform_dg_harmonic_with(plan, m.points, motion, avx, StepKernel::automatic);
            deform_dg_harmonic_with(plan, m.points, motion, sse, StepKernel::baseline);
            EXPECT_EQ(0, std::memcmp(avx.data(), sse.data(), avx.size() * sizeof(double)))
                << dim << "D, " << (rotates ? "with" : "without") << " rotation";
            EXPECT_NE(0, std::memcmp(sse.data(), m.points.data(), sse.size() * sizeof(double)));  // it moved
            // And deform_dg_harmonic is the automatic choice.
            std::vector<double> plain(m.points.size());
            deform_dg_harmonic(plan, m.points, motion, plain);
            EXPECT_EQ(0, std::memcmp(plain.data(), avx.data(), avx.size() * sizeof(double)));
        }
    }
}

// With two threads the coarse solve is split: each thread solves half of the
// carried components (or the translation and the rotation systems side by
// side). Every motion kind takes its own branch: translation only, rotation
// only, both; one shared factor (3D) or two (2D). The bits must be those of
// one thread.
TEST(DgHarmonicStep, TwoThreadsSplittingTheCoarseSolveGiveTheSameBits) {
    const int threads = num_threads();
    for (int dim : {2, 3}) {
        const BoxInBox m = jittered(box_in_box(dim, dim == 2 ? 24 : 10), 0.02, 7);
        const DgHarmonicPlan plan = prepare_dg_harmonic(dim, m.points, m.boundary, {.wall_spacing = 2.0, .growth = 0.5});
        ASSERT_GT(plan.stats.coarse_interior, 0);
        EXPECT_EQ(plan.solve.shared, dim == 3);
        for (int kind = 0; kind < 3; ++kind) {  // translation only, rotation only, both
            BoundaryMotion motion = random_motion(m, 9, 0.1);
            for (NodeMotion& nm : motion) {
                if (kind == 0) nm.rotation = {};
                if (kind == 1) nm.translation = {};
            }
            std::vector<double> one(m.points.size()), two(m.points.size());
            set_num_threads(1);
            deform_dg_harmonic(plan, m.points, motion, one);
            set_num_threads(2);
            deform_dg_harmonic(plan, m.points, motion, two);
            set_num_threads(threads);
            EXPECT_EQ(0, std::memcmp(one.data(), two.data(), one.size() * sizeof(double))) << dim << "D, kind " << kind;
            EXPECT_NE(0, std::memcmp(one.data(), m.points.data(), one.size() * sizeof(double)));  // it moved
        }
    }
}
