#pragma once
// Internal to picture/: the parts write_mesh_picture draws, each on a cairo
// context whose user space is the image's pixels.
#include <cairo.h>

#include <span>
#include <string>

#include "dgwarp/mesh/mesh.hpp"
#include "dgwarp/picture/picture_layout.hpp"

namespace dgwarp::picture_detail {

/// Fills the cells that meet layout.window (values as in write_mesh_picture,
/// used when layout.colored), strokes their edges `edge_width_px` wide and the
/// mesh's marker lines on top, all clipped to layout.plot; frames the plot
/// when some cell reaches outside it.
void draw_mesh(cairo_t* cr, const PictureLayout& layout, const Mesh& mesh, std::span<const double> cell_values,
               double edge_width_px);

/// The colour bar right of layout.plot: the map from 0 (bottom) to 1 (top),
/// ticks 0, 0.25, 0.5, 0.75, 1, `label` above it and the inverted colour below.
void draw_colorbar(cairo_t* cr, const PictureLayout& layout, const std::string& label);

/// `title` centred in the band above layout.plot.
void draw_title(cairo_t* cr, const PictureLayout& layout, const std::string& title);

}  // namespace dgwarp::picture_detail
