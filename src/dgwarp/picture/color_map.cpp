#include "dgwarp/picture/color_map.hpp"

#include <algorithm>
#include <array>
#include <cmath>

namespace dgwarp {

namespace {

constexpr Rgb from_8bit(int r, int g, int b) { return {r / 255.0, g / 255.0, b / 255.0}; }

// Matplotlib's viridis sampled at 11 evenly spaced values (#440154 ... #fde725).
constexpr std::array<Rgb, 11> viridis = {
    from_8bit(0x44, 0x01, 0x54), from_8bit(0x48, 0x24, 0x75), from_8bit(0x41, 0x44, 0x87),
    from_8bit(0x35, 0x5f, 0x8d), from_8bit(0x2a, 0x78, 0x8e), from_8bit(0x21, 0x91, 0x8c),
    from_8bit(0x22, 0xa8, 0x84), from_8bit(0x44, 0xbf, 0x70), from_8bit(0x7a, 0xd1, 0x51),
    from_8bit(0xbd, 0xdf, 0x26), from_8bit(0xfd, 0xe7, 0x25)};

}  // namespace

std::span<const Rgb> colors_of_map() { return viridis; }

Rgb value_color(double value) {
    if (!(value > 0)) return inverted_color;  // also NaN
    const double t = std::min(value, 1.0) * (viridis.size() - 1);
    const std::size_t k = std::min(static_cast<std::size_t>(t), viridis.size() - 2);
    const double f = t - static_cast<double>(k);
    const Rgb& a = viridis[k];
    const Rgb& b = viridis[k + 1];
    return {a.r + f * (b.r - a.r), a.g + f * (b.g - a.g), a.b + f * (b.b - a.b)};
}

}  // namespace dgwarp
