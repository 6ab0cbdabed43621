#include "dgwarp/picture/picture_layout.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "dgwarp/core/error.hpp"
#include "dgwarp/picture/picture_window.hpp"

namespace dgwarp {

namespace {

std::string window_text(const std::array<double, 4>& w) {
    return std::to_string(w[0]) + " " + std::to_string(w[1]) + " " + std::to_string(w[2]) + " " +
           std::to_string(w[3]);
}

std::array<double, 4> default_window(const Mesh& mesh) {
    const BoundingBox box = bounding_box(mesh);
    double w = box.max[0] - box.min[0], h = box.max[1] - box.min[1];
    if (w == 0 && h == 0) w = h = 1;  // a mesh of one point still gets a window
    const double margin = 0.04 * std::max(w, h);
    return {box.min[0] - margin, box.max[0] + margin, box.min[1] - margin, box.max[1] + margin};
}

}  // namespace

PictureLayout picture_layout(const Mesh& mesh, std::span<const double> cell_values, const PictureOptions& o) {
    if (o.width < min_picture_size || o.width > max_picture_size || o.height < min_picture_size ||
        o.height > max_picture_size)
        throw Error("picture: image size must be " + std::to_string(min_picture_size) + " .. " +
                    std::to_string(max_picture_size) + " pixels, got " + std::to_string(o.width) + " x " +
                    std::to_string(o.height));
    if (o.window) {
        const auto& w = *o.window;
        if (!std::all_of(w.begin(), w.end(), [](double v) { return std::isfinite(v); }) || !(w[0] < w[1]) ||
            !(w[2] < w[3]))
            throw Error("picture: window must be finite with xmin < xmax and ymin < ymax, got " + window_text(w));
    }
    PictureLayout layout;
    layout.width = o.width;
    layout.height = o.height;
    layout.colored = o.color_by_quality && !cell_values.empty();
    layout.colorbar = layout.colored && o.colorbar;
    layout.font_px = std::clamp(std::min(o.width, o.height) / 42.0, 11.0, 48.0);

    const double f = layout.font_px;
    const double margin = 0.8 * f;
    const double top = o.title.empty() ? margin : margin + 2.0 * f;
    const double bar_band = layout.colorbar ? 7.0 * f : 0.0;
    // Tiny images keep at least a pixel to draw in.
    const double plot_w = std::max(1.0, o.width - 2 * margin - bar_band);
    const double plot_h = std::max(1.0, o.height - top - margin);
    layout.plot = {margin, top, plot_w, plot_h};

    const std::array<double, 4> wanted = o.window ? *o.window : default_window(mesh);
    layout.window = enlarge_to_aspect(wanted, plot_w / plot_h);
    layout.scale = plot_w / (layout.window[1] - layout.window[0]);
    return layout;
}

}  // namespace dgwarp
