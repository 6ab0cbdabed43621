#pragma once
// The colours of mesh pictures: a viridis colour map for values in [0, 1]
// (perceptually uniform, readable in grey and by colour-blind readers) and a
// red that is not in the map for inverted cells.
#include <span>

namespace dgwarp {

/// A colour, each channel in [0, 1].
struct Rgb {
    double r = 0, g = 0, b = 0;
    bool operator==(const Rgb&) const = default;
};

inline constexpr Rgb background_color{1.0, 1.0, 1.0};      // where there are no cells
inline constexpr Rgb inverted_color{0.86, 0.08, 0.12};     // value <= 0 (or NaN)
inline constexpr Rgb plain_cell_color{0.90, 0.91, 0.93};   // cells drawn without values

/// The colour map's table: colors_of_map()[k] is the colour of value
/// k / (size - 1); values between entries are interpolated linearly.
std::span<const Rgb> colors_of_map();

/// The colour of a cell value: inverted_color when value <= 0 or NaN, else
/// the map's colour of min(value, 1).
Rgb value_color(double value);

}  // namespace dgwarp
