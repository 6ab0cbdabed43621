#pragma once
// PNG pictures of 2D meshes, cells coloured by a per-cell value (usually the
// shape quality, quality/mesh_quality.hpp), the way the DG-IDW paper shows its
// results: the whole mesh, and close-ups near a wall (window_around).
// Pictures are an output format: this folder draws, it computes nothing else.
#include <filesystem>
#include <span>

#include "dgwarp/mesh/mesh.hpp"
#include "dgwarp/picture/picture_options.hpp"
#include "dgwarp/picture/picture_window.hpp"

namespace dgwarp {

/// Writes a PNG of the 2D mesh (options.width × options.height pixels, RGB)
/// showing the cells that meet the view window (see picture_layout):
/// each cell filled with value_color(cell_values[i]) (color_map.hpp: viridis
/// over [0, 1], red for values <= 0, which are drawn last so they are never
/// hidden), or light grey when cell_values is empty or
/// options.color_by_quality is false; cell edges thin and dark (over coloured
/// cells they fade out where cells are smaller than a few pixels, so dense
/// regions keep their colour); marker lines thick and black; a thin grey frame
/// when the window cuts cells off; the title above and a colour bar (ticks 0,
/// 0.25, 0.5, 0.75, 1 and an "inverted" swatch) on the right.
/// `mesh.points` is num_points × 2, row-major; `cell_values` has one value per
/// cell (mesh.cells order) or is empty.
/// The file is written through write_file_atomically: on any error a file
/// already at `png` is left as it was. Throws MeshError for a 3D mesh
/// ("pictures are 2D only"), an inconsistent mesh (validate) or a cell_values
/// of the wrong size; Error for bad options (see picture_layout; a negative
/// or non-finite edge width); IoError when the file cannot be written.
void write_mesh_picture(const std::filesystem::path& png, const Mesh& mesh, std::span<const double> cell_values,
                        const PictureOptions& options = {});

}  // namespace dgwarp
