#pragma once
// A uniform Cartesian grid of a square box with a rectangular hole: the mesh
// of the paper's bar-in-a-box case (twisted_bar.hpp).
#include "dgwarp/mesh/mesh.hpp"

namespace dgwarp {

struct GridWithHoleOptions {
    double box_half_size = 10.0;  // the box is [-h, h]²
    int cells = 49;               // cells along each side of the box (uniform squares)
    int rect_cells_x = 21;        // the hole (centred at the origin) spans this many
    int rect_cells_y = 9;         //   cells in x and in y; cells - rect_cells_* must be even
};

/// The grid with the hole cut out: 2D, counter-clockwise quadrilaterals,
/// markers "rectangle" (the hole's loop) and "farfield", each a closed loop
/// run counter-clockwise. (cells+1)² - (rect_cells_x-1)(rect_cells_y-1) nodes
/// and cells² - rect_cells_x·rect_cells_y cells. Throws MeshError when the
/// hole does not fit in the box or is not centred on grid lines.
Mesh make_grid_with_hole(const GridWithHoleOptions& options = {});

}  // namespace dgwarp
