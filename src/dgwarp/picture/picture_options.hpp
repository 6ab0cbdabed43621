#pragma once
// Options of a mesh picture (write_mesh_picture): plain data with defaults.
#include <array>
#include <optional>
#include <string>

namespace dgwarp {

/// The image sizes a picture may have, in pixels (Cairo's image surfaces are
/// at most 32767 pixels wide).
inline constexpr int min_picture_size = 16, max_picture_size = 32767;

struct PictureOptions {
    int width = 1600;   // image size in pixels (min_picture_size .. max_picture_size)
    int height = 1200;
    /// View window in mesh coordinates: xmin, xmax, ymin, ymax. Default: the
    /// mesh's bounding box with a small margin. Either way the window is
    /// enlarged about its centre to the drawing area's aspect ratio, so the
    /// mesh is never stretched (see window_around for close-ups).
    std::optional<std::array<double, 4>> window;
    bool color_by_quality = true;     // fill cells with the colour map of their value
    double edge_width_px = 0.5;       // cell edges; 0 draws none (marker lines are always drawn)
    std::string title;                // drawn above the mesh when not empty
    bool colorbar = true;             // colour bar on the right (when cells are coloured)
    std::string colorbar_label = "quality";  // text above the colour bar
};

}  // namespace dgwarp
