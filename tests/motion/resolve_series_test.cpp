// A time series resolves each frame from what resolve_boundary built once:
// resolve_frame reads only its own frame of the spec, so a series of F frames
// costs O(F) (before, each frame rebuilt the context from every frame: O(F²)).
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <numbers>
#include <variant>
#include <vector>

#include "dgwarp/motion/resolve_motion.hpp"
#include "motion/motion_test_meshes.hpp"

using namespace dgwarp;
using dgwarp::test::two_squares;

namespace {

constexpr std::size_t series_frames = 10'000;

/// Frame k moves the airfoil by (k·1e-5, 0) and turns it by k·1e-5 rad.
MotionSpec series_frame_list() {
    MotionSpec spec;
    spec.frames.resize(series_frames);
    for (std::size_t k = 0; k < series_frames; ++k) {
        const double s = 1e-5 * static_cast<double>(k);
        spec.frames[k].markers["airfoil"] = RigidMotion{NodeMotion{{s, 0, 0}, {0, 0, s}, {0, 0, 0}}};
    }
    return spec;
}

/// A pitching motion of 10,000 steps (two degrees at 1 Hz, 1 ms steps).
MotionSpec series_pitching() {
    MotionSpec spec;
    spec.frames.resize(1);
    Pitch pitch;
    pitch.amplitude = 2 * std::numbers::pi / 180;
    pitch.frequency = 1;
    pitch.center = {0.25, 0, 0};
    spec.frames[0].markers["airfoil"] = PeriodicMotion{pitch, std::nullopt};
    spec.time = TimeSteps{1e-3, static_cast<std::int64_t>(series_frames)};
    return spec;
}

/// Bitwise equality of two boundary motions (NaN-safe, -0 ≠ +0).
bool series_same_bits(const BoundaryMotion& a, const BoundaryMotion& b) {
    return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(NodeMotion)) == 0;
}

}  // namespace

TEST(MotionResolveSeries, AFrameReadsOnlyItsOwnFrameOfTheSpec) {
    const Mesh mesh = two_squares();
    const MotionSpec spec = series_frame_list();
    const ResolvedBoundary rb = resolve_boundary(mesh, spec);
    const BoundaryMotion frame_7 = resolve_frame(mesh, spec, rb, 7).motion;
    // Damage every other frame (an unknown marker, a marker made fixed): had
    // resolve_frame rebuilt its context from all frames, it would throw or
    // reclassify the boundary; it reads frame 7 alone and gives the same bits.
    MotionSpec others = spec;
    for (std::size_t k = 0; k < series_frames; ++k) {
        if (k == 7) continue;
        others.frames[k].markers.clear();
        others.frames[k].markers["no-such-marker"] = FixedMotion{};
    }
    EXPECT_TRUE(series_same_bits(resolve_frame(mesh, others, rb, 7).motion, frame_7));
}

TEST(MotionResolveSeries, TenThousandFramesAgreeWithFramesResolvedAlone) {
    const Mesh mesh = two_squares();
    for (const MotionSpec& spec : {series_frame_list(), series_pitching()}) {
        ASSERT_EQ(frame_count(spec), series_frames);
        const ResolvedBoundary rb = resolve_boundary(mesh, spec);
        std::vector<BoundaryMotion> series;
        series.reserve(series_frames);
        for (std::size_t k = 0; k < series_frames; ++k) series.push_back(resolve_frame(mesh, spec, rb, k).motion);
        // Each checked frame as a one-off: its own resolve_boundary, then the frame.
        for (std::size_t k : {std::size_t{0}, std::size_t{1}, std::size_t{4'999}, series_frames - 1}) {
            const ResolvedBoundary alone = resolve_boundary(mesh, spec);
            EXPECT_TRUE(series_same_bits(series[k], resolve_frame(mesh, spec, alone, k).motion)) << k;
            // And what the motion says, node by node.
            for (std::size_t b = 0; b < rb.boundary.nodes.size(); ++b) {
                const MarkerMotion& m = spec.frames[spec.time ? 0 : k].markers.at("airfoil");
                const NodeMotion expected =
                    !rb.boundary.moving[b]                    ? NodeMotion{}
                    : std::holds_alternative<RigidMotion>(m) ? std::get<RigidMotion>(m).motion
                                                             : periodic_motion_at(std::get<PeriodicMotion>(m),
                                                                                  frame_time(spec, k));
                EXPECT_EQ(series[k][b], expected) << "frame " << k << ", boundary node " << b;
            }
        }
    }
}
