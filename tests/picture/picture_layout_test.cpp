// Layout of pictures and close-up windows: the visible window keeps the
// drawing area's aspect ratio and contains what was asked for, the map to
// pixels sends the window's corners to the drawing area's corners, and
// window_around frames the given nodes (hand-computed boxes).
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

#include "dgwarp/cases/rect_box.hpp"
#include "dgwarp/core/error.hpp"
#include "dgwarp/picture/picture_layout.hpp"
#include "dgwarp/picture/picture_window.hpp"
#include "support/picture_test_box.hpp"

using namespace dgwarp;
using dgwarp::test::picture_test_box;

namespace {

void expect_window(const std::array<double, 4>& got, const std::array<double, 4>& want) {
    for (int k = 0; k < 4; ++k) EXPECT_NEAR(got[k], want[k], 1e-12) << "entry " << k;
}

// Checks the layout's invariants; `wanted` must lie within the visible window.
void check_layout(const PictureLayout& l, const std::array<double, 4>& wanted) {
    EXPECT_GE(l.plot[0], 0);
    EXPECT_GE(l.plot[1], 0);
    EXPECT_LE(l.plot[0] + l.plot[2], l.width);
    EXPECT_LE(l.plot[1] + l.plot[3], l.height);
    const double ww = l.window[1] - l.window[0], wh = l.window[3] - l.window[2];
    EXPECT_NEAR(ww / wh, l.plot[2] / l.plot[3], 1e-12);
    EXPECT_NEAR(l.scale, l.plot[2] / ww, 1e-9 * l.scale);
    EXPECT_LE(l.window[0], wanted[0] + 1e-12);
    EXPECT_GE(l.window[1], wanted[1] - 1e-12);
    EXPECT_LE(l.window[2], wanted[2] + 1e-12);
    EXPECT_GE(l.window[3], wanted[3] - 1e-12);
    // Same centre as asked, and tight in one direction.
    EXPECT_NEAR(l.window[0] + l.window[1], wanted[0] + wanted[1], 1e-9);
    EXPECT_NEAR(l.window[2] + l.window[3], wanted[2] + wanted[3], 1e-9);
    const bool tight_x = std::fabs(ww - (wanted[1] - wanted[0])) < 1e-9;
    const bool tight_y = std::fabs(wh - (wanted[3] - wanted[2])) < 1e-9;
    EXPECT_TRUE(tight_x || tight_y);
    const auto top_left = to_pixel(l, l.window[0], l.window[3]);
    const auto bottom_right = to_pixel(l, l.window[1], l.window[2]);
    EXPECT_NEAR(top_left[0], l.plot[0], 1e-9);
    EXPECT_NEAR(top_left[1], l.plot[1], 1e-9);
    EXPECT_NEAR(bottom_right[0], l.plot[0] + l.plot[2], 1e-9);
    EXPECT_NEAR(bottom_right[1], l.plot[1] + l.plot[3], 1e-9);
}

}  // namespace

TEST(PictureLayout, DefaultWindowIsTheBoundingBoxWithAMargin) {
    const Mesh mesh = make_rect_box(picture_test_box);  // box [-6, 6]²
    const std::vector<double> values(mesh.cells.size(), 0.5);
    const PictureLayout l = picture_layout(mesh, values, {});
    EXPECT_EQ(l.width, 1600);
    EXPECT_EQ(l.height, 1200);
    EXPECT_TRUE(l.colored);
    EXPECT_TRUE(l.colorbar);
    const double m = 0.04 * 12;
    check_layout(l, {-6 - m, 6 + m, -6 - m, 6 + m});
}

TEST(PictureLayout, AGivenWindowIsKeptAndEnlargedToTheAspect) {
    const Mesh mesh = make_rect_box(picture_test_box);
    PictureOptions o;
    o.width = 900;
    o.height = 300;
    for (const std::array<double, 4> w : {std::array<double, 4>{0.5, 1.5, -0.2, 0.2}, {-1, 1, -3, 3}}) {
        o.window = w;
        check_layout(picture_layout(mesh, {}, o), w);
    }
}

TEST(PictureLayout, ColorBarAndTitleTakeTheirBands) {
    const Mesh mesh = make_rect_box(picture_test_box);
    const std::vector<double> values(mesh.cells.size(), 0.5);
    PictureOptions o;
    const PictureLayout with_bar = picture_layout(mesh, values, o);
    const PictureLayout no_values = picture_layout(mesh, {}, o);
    o.colorbar = false;
    const PictureLayout no_bar = picture_layout(mesh, values, o);
    EXPECT_LT(with_bar.plot[2], no_bar.plot[2]);
    EXPECT_EQ(no_values.plot, no_bar.plot);
    EXPECT_FALSE(no_values.colored);
    EXPECT_FALSE(no_values.colorbar);
    EXPECT_TRUE(no_bar.colored);
    EXPECT_FALSE(no_bar.colorbar);
    o.color_by_quality = false;
    EXPECT_FALSE(picture_layout(mesh, values, o).colored);
    o.title = "rectangle in a box";
    const PictureLayout titled = picture_layout(mesh, values, o);
    EXPECT_GT(titled.plot[1], no_bar.plot[1]);
    EXPECT_GT(titled.plot[1] - no_bar.plot[1], titled.font_px);  // room for a line of text
}

TEST(PictureLayout, BadSizesAndWindowsAreRefused) {
    const Mesh mesh = make_rect_box(picture_test_box);
    const double nan = std::numeric_limits<double>::quiet_NaN();
    for (const std::array<double, 4> w : {std::array<double, 4>{1, 1, 0, 1}, {2, 1, 0, 1}, {0, 1, 1, 0},
                                          {0, nan, 0, 1}, {0, 1, 0, INFINITY}}) {
        PictureOptions o;
        o.window = w;
        EXPECT_THROW(picture_layout(mesh, {}, o), Error);
    }
    PictureOptions tiny;
    tiny.width = 8;
    EXPECT_THROW(picture_layout(mesh, {}, tiny), Error);
    PictureOptions huge;
    huge.height = 40000;
    EXPECT_THROW(picture_layout(mesh, {}, huge), Error);
}

TEST(PictureWindow, EnlargeToAspectKeepsCentreAndContainsTheWindow) {
    expect_window(enlarge_to_aspect({0, 2, 0, 1}, 2.0), {0, 2, 0, 1});
    expect_window(enlarge_to_aspect({0, 2, 0, 1}, 1.0), {0, 2, -0.5, 1.5});
    expect_window(enlarge_to_aspect({0, 2, 0, 1}, 4.0), {-1, 3, 0, 1});
    expect_window(enlarge_to_aspect({3, 3, 5, 5}, 1.5), {3, 3, 5, 5});
}

TEST(PictureWindow, WindowAroundFramesTheNodes) {
    Mesh mesh;
    mesh.dim = 2;
    mesh.points = {0, 0, 2, 1, 10, 10, -10, -10};
    const NodeId two[] = {0, 1};
    // Box [0, 2] × [0, 1], centre (1, 0.5), half sizes 1 and 0.5, doubled: 2 and 1.
    expect_window(window_around(mesh, two, 2.0, 2.0), {-1, 3, -0.5, 1.5});
    expect_window(window_around(mesh, two, 2.0, 4.0 / 3.0), {-1, 3, -1, 2});
    expect_window(window_around(mesh, two, 2.0, 0.5), {-1, 3, -3.5, 4.5});
    // Nodes on a horizontal line still give a window of some height.
    const NodeId flat[] = {0, 2};
    mesh.points[5] = 0;  // node 2 at (10, 0)
    expect_window(window_around(mesh, flat, 1.0, 2.0), {0, 10, -2.5, 2.5});
    // One node: 1% of the mesh's bounding-box diagonal (mesh box [-10, 10]²).
    mesh.points[5] = 10;
    const NodeId one[] = {1};
    const double half = 0.005 * std::hypot(20.0, 20.0) * 3.0;
    expect_window(window_around(mesh, one, 3.0, 1.0), {2 - half, 2 + half, 1 - half, 1 + half});
}

TEST(PictureWindow, WindowAroundRefusesBadInput) {
    const Mesh mesh = make_rect_box(picture_test_box);
    EXPECT_THROW(window_around(mesh, {}, 1.5), MeshError);
    const NodeId bad[] = {0, 5, static_cast<NodeId>(mesh.num_points())};
    try {
        window_around(mesh, bad, 1.5);
        ADD_FAILURE() << "no error for an out-of-range node";
    } catch (const MeshError& e) {
        EXPECT_EQ(e.index(), 2);
    }
    const NodeId good[] = {0, 5};
    EXPECT_THROW(window_around(mesh, good, 0.0), Error);
    EXPECT_THROW(window_around(mesh, good, std::numeric_limits<double>::quiet_NaN()), Error);
    EXPECT_THROW(window_around(mesh, good, 1.5, -1.0), Error);
}
