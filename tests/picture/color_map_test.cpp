// The colour map of pictures: table ends, linear interpolation between
// entries, the inverted colour for values <= 0, and viridis's defining
// property (lightness grows with the value).
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "dgwarp/picture/color_map.hpp"

using namespace dgwarp;

namespace {

void expect_near(const Rgb& a, const Rgb& b, double tol = 1e-12) {
    EXPECT_NEAR(a.r, b.r, tol);
    EXPECT_NEAR(a.g, b.g, tol);
    EXPECT_NEAR(a.b, b.b, tol);
}

double luminance(const Rgb& c) { return 0.2126 * c.r + 0.7152 * c.g + 0.0722 * c.b; }

}  // namespace

TEST(PictureColorMap, EndsAreViridisDarkPurpleAndYellow) {
    const auto map = colors_of_map();
    ASSERT_GE(map.size(), 2u);
    expect_near(map.front(), {0x44 / 255.0, 0x01 / 255.0, 0x54 / 255.0});
    expect_near(map.back(), {0xfd / 255.0, 0xe7 / 255.0, 0x25 / 255.0});
    expect_near(value_color(1.0), map.back());
    expect_near(value_color(1.0 + 1e-9), map.back());  // round-off above 1
    expect_near(value_color(7.0), map.back());
    expect_near(value_color(1e-300), map.front(), 1e-9);
}

TEST(PictureColorMap, InterpolatesLinearlyBetweenEntries) {
    const auto map = colors_of_map();
    const double step = 1.0 / static_cast<double>(map.size() - 1);
    for (std::size_t k = 0; k + 1 < map.size(); ++k) {
        if (k > 0) expect_near(value_color(k * step), map[k], 1e-9);
        const Rgb& a = map[k];
        const Rgb& b = map[k + 1];
        expect_near(value_color((k + 0.25) * step), {0.75 * a.r + 0.25 * b.r, 0.75 * a.g + 0.25 * b.g,
                                                     0.75 * a.b + 0.25 * b.b},
                    1e-9);
    }
}

TEST(PictureColorMap, ValuesAtOrBelowZeroAndNaNAreInverted) {
    EXPECT_EQ(value_color(0.0), inverted_color);
    EXPECT_EQ(value_color(-0.185), inverted_color);
    EXPECT_EQ(value_color(-std::numeric_limits<double>::infinity()), inverted_color);
    EXPECT_EQ(value_color(std::numeric_limits<double>::quiet_NaN()), inverted_color);
}

TEST(PictureColorMap, LightnessGrowsWithValueAndInvertedStandsOut) {
    double previous = -1;
    for (int i = 1; i <= 200; ++i) {
        const Rgb c = value_color(i / 200.0);
        EXPECT_GT(luminance(c), previous) << "value " << i / 200.0;
        previous = luminance(c);
        const double distance = std::hypot(c.r - inverted_color.r, c.g - inverted_color.g, c.b - inverted_color.b);
        EXPECT_GT(distance, 0.4) << "value " << i / 200.0 << " looks like the inverted colour";
    }
}
