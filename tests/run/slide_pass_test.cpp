// Sliding markers in a run (run/slide_pass.hpp): a box squeezed from its top
// with its sides sliding.
#include "dgwarp/run/slide_pass.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "dgwarp/run/run_deformation.hpp"
#include "support/lattice_box.hpp"

namespace dgwarp {
namespace {

MotionSpec squeeze(bool sides_slide) {
    MotionSpec spec;
    MotionFrame frame;
    frame.markers["y_p"] = RigidMotion{NodeMotion{{0, -0.2, 0}, {0, 0, 0}, {0, 0, 0}}};
    if (sides_slide) frame.markers["x_m"] = frame.markers["x_p"] = SlideMotion{};
    spec.frames.push_back(frame);
    spec.source = "squeeze";
    return spec;
}

TEST(SlidePass, SidesSlideDownAndTheBoxStaysValidForEveryMethod) {
    const int n = 9;
    const Mesh mesh = test::lattice_box(2, n);  // node i + n j at (i, j) / (n - 1)
    for (const Method method : all_methods) {
        SCOPED_TRACE(std::string(method_name(method)));
        const MotionSpec spec = squeeze(true);
        const Deformation d = prepare_deformation(mesh, spec, method);
        ASSERT_TRUE(d.slide.has_value());
        EXPECT_EQ(d.boundary.slides.size(), 2u * (n - 2));
        std::vector<double> moved;
        RunCallbacks on;
        on.frame_done = [&](const FrameView& f) {
            moved.assign(f.points.begin(), f.points.end());
            // The first pass is RBF's for every method (slide_pass_method):
            // the sides come down evenly, and every method keeps the box valid.
            EXPECT_TRUE(f.report.valid()) << f.report.inverted_by_motion << " inverted";
            return true;
        };
        run_frames(RunContext::of(mesh, spec, d), {}, on);
        ASSERT_EQ(moved.size(), mesh.points.size());
        for (const int i : {0, n - 1}) {
            double below = -1;
            for (int j = 0; j < n; ++j) {
                const std::size_t node = static_cast<std::size_t>(i + n * j);
                // On its line x = 0 or 1 exactly; moved down, by at most the top's 0.2; in order.
                EXPECT_EQ(moved[2 * node], mesh.points[2 * node]) << node;
                const double dy = moved[2 * node + 1] - mesh.points[2 * node + 1];
                EXPECT_LE(dy, 1e-12) << node;
                EXPECT_GE(dy, -0.2 - 1e-12) << node;
                EXPECT_GT(moved[2 * node + 1], below) << node;
                below = moved[2 * node + 1];
            }
            // The top corner went down with the top, the bottom one stayed.
            EXPECT_DOUBLE_EQ(moved[2 * static_cast<std::size_t>(i + n * (n - 1)) + 1], 0.8);
            EXPECT_EQ(moved[2 * static_cast<std::size_t>(i) + 1], 0.0);
        }
    }
}

TEST(SlidePass, SlidingSidesLetTheSqueezeBeUniform) {
    // Fixed sides hold their nodes, so the cells beside them shear; sliding
    // ones follow the squeeze: DG-harmonic's worst cell is better.
    const Mesh mesh = test::lattice_box(2, 9);
    double worst[2] = {0, 0};
    for (const bool slide : {false, true}) {
        const MotionSpec spec = squeeze(slide);
        const Deformation d = prepare_deformation(mesh, spec, Method::dg_harmonic);
        RunCallbacks on;
        on.frame_done = [&](const FrameView& f) {
            worst[slide] = f.report.quality.min;
            return true;
        };
        run_frames(RunContext::of(mesh, spec, d), {}, on);
    }
    EXPECT_GT(worst[1], worst[0]);
    EXPECT_GT(worst[1], 0.9);  // a uniform squeeze of squares by 0.8: Knupp's shape quality about 0.98
}

TEST(SlidePass, CyclicSidesMoveAsTheirImagesForEveryMethod) {
    // The top of a periodic box (x_m and x_p cyclic) sheared by 0.15 along x
    // and lowered by 0.1: each side node moves exactly as its image, and every
    // method keeps the box valid. With the sides fixed instead, the shear
    // bends the cells against them.
    const int n = 9;
    const Mesh mesh = test::lattice_box(2, n);
    MotionSpec spec;
    MotionFrame frame;
    frame.markers["y_p"] = RigidMotion{NodeMotion{{0.15, -0.1, 0}, {0, 0, 0}, {0, 0, 0}}};
    frame.markers["x_m"] = CyclicMotion{"x_p"};
    frame.markers["x_p"] = CyclicMotion{"x_m"};
    spec.frames.push_back(frame);
    for (const Method method : all_methods) {
        SCOPED_TRACE(std::string(method_name(method)));
        const Deformation d = prepare_deformation(mesh, spec, method);
        ASSERT_TRUE(d.slide.has_value());
        std::vector<double> moved;
        RunCallbacks on;
        on.frame_done = [&](const FrameView& f) {
            EXPECT_TRUE(f.report.valid()) << f.report.inverted_by_motion << " inverted";
            moved.assign(f.points.begin(), f.points.end());
            return true;
        };
        run_frames(RunContext::of(mesh, spec, d), {}, on);
        ASSERT_EQ(moved.size(), mesh.points.size());
        double largest = 0;
        for (int j = 1; j + 1 < n; ++j) {
            const auto a = static_cast<std::size_t>(n * j), b = a + static_cast<std::size_t>(n - 1);
            for (std::size_t k = 0; k < 2; ++k) {
                const double da = moved[2 * a + k] - mesh.points[2 * a + k], db = moved[2 * b + k] - mesh.points[2 * b + k];
                EXPECT_NEAR(da, db, 1e-14) << "node " << a << ", component " << k;
                largest = std::max(largest, std::abs(da));
            }
        }
        EXPECT_GT(largest, 0.01);  // the sides followed the shear
    }
}

}  // namespace
}  // namespace dgwarp
