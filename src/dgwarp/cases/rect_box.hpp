#pragma once
// The paper's first test case (section 3.1, Fig. 8): a rectangle in a square
// box, meshed with structured quadrilaterals, 2,340 nodes by default.
#include "dgwarp/mesh/mesh.hpp"

namespace dgwarp {

struct RectBoxOptions {
    double box_half_size = 10.0;  // the box is [-h, h]²
    int cells = 49;               // cells along each side of the box (uniform squares)
    int rect_cells_x = 21;        // the rectangle (centred at the origin) spans this many
    int rect_cells_y = 9;         //   cells in x and in y; cells - rect_cells_* must be even
};

/// A uniform Cartesian grid of the box with the rectangle cut out: 2D,
/// counter-clockwise quadrilaterals, markers "rectangle" and "farfield". The
/// defaults give 50² - 20·8 = 2,340 nodes and 49² - 21·9 = 2,212 cells, the
/// rectangle 8.57 × 3.67 in a 20 × 20 box (the paper gives the node count and
/// a figure, not the dimensions). Throws MeshError when the rectangle does not
/// fit in the box or is not centred on grid lines.
Mesh make_rect_box(const RectBoxOptions& options = {});

}  // namespace dgwarp
