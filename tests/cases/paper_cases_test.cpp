#include "dgwarp/cases/paper_cases.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "dgwarp/cases/sphere_box.hpp"
#include "dgwarp/core/error.hpp"
#include "dgwarp/motion/resolve_motion.hpp"

using namespace dgwarp;

namespace {
/// New positions of the boundary nodes under motion `m` (BoundarySet order), and the boundary.
std::pair<std::vector<double>, ResolvedBoundary> moved(const Mesh& mesh, const CaseMotion& m) {
    ResolvedBoundary b = resolve_boundary(mesh, m.spec);
    const ResolvedFrame f = resolve_frame(mesh, m.spec, b, 0);
    return {moved_boundary_points(mesh, b.boundary, f.motion), std::move(b)};
}
}  // namespace

TEST(CasesPaper, NamesSizesAndUnknownNames) {
    // The paper's five in its order, then ours (issue #12).
    EXPECT_EQ(case_names(), (std::vector<std::string>{"rect-box", "naca0012", "twisted-bar", "squeezed-sphere",
                                                      "wing-body", "two-element", "store"}));
    EXPECT_EQ(case_size_count("squeezed-sphere"), 3);
    EXPECT_EQ(case_size_count("naca0012"), 1);
    EXPECT_THROW(make_case("nope"), Error);
    EXPECT_THROW(make_case("rect-box", 1), Error);
    EXPECT_THROW(case_motions("nope", Mesh{}), Error);
}

TEST(CasesPaper, TwoDimensionalMotionsResolveAndMoveOnlyTheBody) {
    for (const std::string name : {"rect-box", "naca0012", "twisted-bar"}) {
        const Mesh mesh = make_case(name);
        const auto motions = case_motions(name, mesh);
        EXPECT_GE(motions.size(), 2u) << name;
        for (const CaseMotion& m : motions) {
            const auto [points, b] = moved(mesh, m);
            ASSERT_EQ(b.moving_markers.size(), 1u) << name << " " << m.name;
            EXPECT_EQ(b.static_markers, std::vector<std::string>{"farfield"}) << name << " " << m.name;
            for (std::size_t i = 0; i < b.boundary.nodes.size(); ++i) {
                if (b.boundary.moving[i]) continue;
                for (int k = 0; k < 2; ++k) ASSERT_EQ(points[2 * i + k], mesh.points[2 * b.boundary.nodes[i] + k]);
            }
        }
    }
}

TEST(CasesPaper, RectBoxRotationTurnsTheCornerByTheAngle) {
    const Mesh mesh = make_case("rect-box");
    const auto motions = case_motions("rect-box", mesh);
    ASSERT_EQ(motions[1].name, "rotate-45");
    const auto [points, b] = moved(mesh, motions[1]);
    const double c = std::cos(std::numbers::pi / 4), s = std::sin(std::numbers::pi / 4);
    for (std::size_t i = 0; i < b.boundary.nodes.size(); ++i) {
        if (!b.boundary.moving[i]) continue;
        const double x = mesh.points[2 * b.boundary.nodes[i]], y = mesh.points[2 * b.boundary.nodes[i] + 1];
        EXPECT_NEAR(points[2 * i], c * x - s * y, 1e-12);
        EXPECT_NEAR(points[2 * i + 1], s * x + c * y, 1e-12);
    }
}

TEST(CasesPaper, TwistTurnsEachSectionAboutItsCentreAndThenTheWholeBar) {
    const Mesh mesh = make_case("twisted-bar");
    const auto motions = case_motions("twisted-bar", mesh);
    ASSERT_EQ(motions.size(), 2u);
    const auto [twisted, b] = moved(mesh, motions[0]);
    const auto [turned, b2] = moved(mesh, motions[1]);
    const double h = 20.0 / 87, x_end = 14.5 * h, pi = std::numbers::pi;
    int checked = 0;
    for (std::size_t i = 0; i < b.boundary.nodes.size(); ++i) {
        if (!b.boundary.moving[i]) continue;
        const double x = mesh.points[2 * b.boundary.nodes[i]], y = mesh.points[2 * b.boundary.nodes[i] + 1];
        const double theta = pi / 4 * x / x_end;  // hand-computed: ±45° at the ends
        EXPECT_NEAR(twisted[2 * i], x - std::sin(theta) * y, 1e-12);
        EXPECT_NEAR(twisted[2 * i + 1], std::cos(theta) * y, 1e-12);
        const double c = std::cos(pi / 4), s = std::sin(pi / 4);
        EXPECT_NEAR(turned[2 * i], c * twisted[2 * i] - s * twisted[2 * i + 1], 1e-12);
        EXPECT_NEAR(turned[2 * i + 1], s * twisted[2 * i] + c * twisted[2 * i + 1], 1e-12);
        ++checked;
    }
    EXPECT_EQ(checked, 2 * (29 + 9));
    // The twist is a displacement (no rotation vector: a shape deformation, as
    // the paper's dx, dy); the rotation that follows is rigid, 45° about the origin.
    for (int k : {0, 1}) {
        const ResolvedFrame f = resolve_frame(mesh, motions[k].spec, b, 0);
        for (std::size_t i = 0; i < f.motion.size(); ++i) {
            if (!b.boundary.moving[i]) continue;
            EXPECT_EQ(f.motion[i].rotation[2], k == 0 ? 0.0 : std::numbers::pi / 4) << i;
            EXPECT_EQ(f.motion[i].center[0], 0.0) << i;
            EXPECT_EQ(f.motion[i].center[1], 0.0) << i;
        }
    }
}

TEST(CasesPaper, SqueezeMovesTheSphereOntoTheEllipsoid) {
    const Mesh mesh = make_sphere_box({0.25, 1.5, 0.2, 1.5, 1});
    const auto motions = case_motions("squeezed-sphere", mesh);
    ASSERT_EQ(motions.size(), 1u);
    const auto [points, b] = moved(mesh, motions[0]);
    EXPECT_EQ(b.moving_markers, std::vector<std::string>{"sphere"});
    for (std::size_t i = 0; i < b.boundary.nodes.size(); ++i) {
        if (!b.boundary.moving[i]) continue;
        const double x = points[3 * i] / 1.1, y = points[3 * i + 1] / 1.1, z = points[3 * i + 2] / 0.8;
        EXPECT_NEAR(x * x + y * y + z * z, 1.0, 1e-6);
    }
}
