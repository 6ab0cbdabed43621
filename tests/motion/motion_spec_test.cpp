#include "dgwarp/motion/motion_spec.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "support/degrees.hpp"

using namespace dgwarp;
using dgwarp::test::deg;

TEST(MotionSpec, RotationVectorIsAngleTimesUnitAxis) {
    const Vec3 w = rotation_vector(0.3, {0, 0, 2});
    EXPECT_DOUBLE_EQ(w[0], 0);
    EXPECT_DOUBLE_EQ(w[1], 0);
    EXPECT_DOUBLE_EQ(w[2], 0.3);
    const Vec3 v = rotation_vector(1.0, {3, 0, 4});
    EXPECT_DOUBLE_EQ(v[0], 0.6);
    EXPECT_DOUBLE_EQ(v[2], 0.8);
}

TEST(MotionSpec, RotationVectorOfATinyOrHugeAxisIsStillAngleTimesUnitAxis) {
    // "any non-zero length" (MOTION.md): [0, 0, 1e-300] squared underflowed
    // to 0 and gave (nan, nan, inf), which deform refused and check passed.
    for (const double length : {1e-300, 4.9e-324, 1e300, 1.7e308}) {
        const Vec3 w = rotation_vector(0.3, {0, 0, length});
        EXPECT_EQ(w, (Vec3{0, 0, 0.3})) << length;
        if (!std::isfinite(4 * length)) continue;
        const Vec3 v = rotation_vector(1.0, {3 * length, 0, 4 * length});
        EXPECT_NEAR(v[0], 0.6, 1e-15) << length;
        EXPECT_NEAR(v[2], 0.8, 1e-15) << length;
    }
}

TEST(MotionSpec, PitchAndPlungeAtHandComputedTimes) {
    PeriodicMotion p;
    p.pitch = Pitch{10 * deg, 2 * deg, 2.0, 30 * deg, {0, 0, 1}, {0.25, 0, 0}};
    p.plunge = Plunge{{0, 0.5, 0}, 1.0, 90 * deg};
    // t = 0: angle = 2° + 10° sin 30° = 7°; plunge = 0.5 sin 90° = 0.5.
    NodeMotion m0 = periodic_motion_at(p, 0.0);
    EXPECT_NEAR(m0.rotation[2], 7 * deg, 1e-15);
    EXPECT_NEAR(m0.translation[1], 0.5, 1e-15);
    EXPECT_EQ(m0.center, (Vec3{0.25, 0, 0}));
    // t = 0.1: angle = 2° + 10° sin(72° + 30°) = 2° + 10° × 0.9781476 = 11.781476°;
    // plunge = 0.5 sin(36° + 90°) = 0.5 × 0.8090170 = 0.4045085.
    NodeMotion m1 = periodic_motion_at(p, 0.1);
    EXPECT_NEAR(m1.rotation[2], 11.781476 * deg, 1e-8);
    EXPECT_NEAR(m1.translation[1], 0.4045085, 1e-7);
    EXPECT_EQ(m1.rotation[0], 0);
    EXPECT_EQ(m1.translation[0], 0);
}

TEST(MotionSpec, FrameCountTimeAndDefault) {
    MotionSpec spec;
    spec.frames.resize(3);
    spec.frames[1].markers["wing"] = RigidMotion{{{1, 0, 0}, {}, {}}};
    spec.default_motion = RigidMotion{{{0, 2, 0}, {}, {}}};
    EXPECT_EQ(frame_count(spec), 3u);
    EXPECT_EQ(frame_time(spec, 2), 0.0);
    EXPECT_EQ(&frame_spec(spec, 1), &spec.frames[1]);
    EXPECT_EQ(std::get<RigidMotion>(marker_motion(spec, spec.frames[1], "wing")).motion.translation[0], 1);
    EXPECT_EQ(&marker_motion(spec, spec.frames[0], "wing"), &spec.default_motion);
    EXPECT_STREQ(motion_kind_name(spec.default_motion), "rigid");

    MotionSpec periodic;
    periodic.frames.resize(1);
    periodic.time = TimeSteps{0.05, 7};
    EXPECT_EQ(frame_count(periodic), 7u);
    EXPECT_DOUBLE_EQ(frame_time(periodic, 4), 0.2);
    EXPECT_EQ(&frame_spec(periodic, 6), &periodic.frames[0]);
}

TEST(MotionSpec, RenameMarkerRenamesTheKeyAndTheCyclicPartnersInEveryFrame) {
    MotionSpec spec;
    spec.frames.resize(2);
    for (MotionFrame& f : spec.frames) {
        f.markers["in 1"] = CyclicMotion{"out"};
        f.markers["out"] = CyclicMotion{"in 1"};
        f.markers["wall"] = FixedMotion{};
    }
    rename_marker(spec, "in 1", "in_1");
    rename_marker(spec, "nosuch", "x");  // no marker of that name: nothing changes
    for (const MotionFrame& f : spec.frames) {
        EXPECT_EQ(f.markers.size(), 3u);
        EXPECT_EQ(f.markers.count("in 1"), 0u);
        EXPECT_EQ(std::get<CyclicMotion>(f.markers.at("in_1")).partner, "out");
        EXPECT_EQ(std::get<CyclicMotion>(f.markers.at("out")).partner, "in_1");
    }
}
