#pragma once
// Where things go in a mesh picture: the drawing area, the visible window of
// the mesh, and the map from mesh coordinates to pixels (y up in the mesh,
// down in the image; one scale for x and y, so shapes are not stretched).
#include <array>
#include <span>

#include "dgwarp/mesh/mesh.hpp"
#include "dgwarp/picture/picture_options.hpp"

namespace dgwarp {

struct PictureLayout {
    int width = 0, height = 0;       // image size in pixels
    std::array<double, 4> plot{};    // drawing area in pixels: left, top, width, height
    std::array<double, 4> window{};  // visible mesh window xmin, xmax, ymin, ymax (the plot's aspect)
    double scale = 0;                // pixels per mesh unit, in x and in y
    double font_px = 0;              // text size in pixels
    bool colored = false;            // cells are filled with the colour map of their values
    bool colorbar = false;           // a colour bar is drawn right of the plot
};

/// The layout write_mesh_picture uses for these arguments: the drawing area is
/// the image less a margin, a title band (when options.title is set) and a
/// colour bar band (when cells are coloured and options.colorbar is set); the
/// visible window is options.window (default: the bounding box of the
/// mesh's points with a margin of 4% of its larger side) enlarged to the drawing area's
/// aspect ratio. `cell_values` has one value per cell or is empty. Throws
/// Error when the image size is outside 16 .. 32767 pixels or
/// options.window is not finite with xmin < xmax and ymin < ymax.
PictureLayout picture_layout(const Mesh& mesh, std::span<const double> cell_values,
                             const PictureOptions& options);

/// The pixel position (x right, y down; pixel (i, j) covers [i, i+1) × [j, j+1))
/// of the mesh point (x, y).
inline std::array<double, 2> to_pixel(const PictureLayout& layout, double x, double y) {
    return {layout.plot[0] + (x - layout.window[0]) * layout.scale,
            layout.plot[1] + (layout.window[3] - y) * layout.scale};
}

}  // namespace dgwarp
