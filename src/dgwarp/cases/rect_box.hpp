#pragma once
// The paper's first test case (section 3.1, Fig. 8): a rectangle in a square
// box, meshed with structured quadrilaterals (an O-grid, 2,340 nodes by default).
//
// The paper gives the node count and a figure, not the dimensions. The sizes
// matter because the paper's DG-IDW weights are not scale invariant (a r^-2
// against r^-1, a = 7): the motion is followed within about a·L = 7 length
// units of the moving body. A 2 × 1 rectangle in a 40 × 40 box reproduces the
// paper's pattern (DG-IDW valid up to 90°, DGM's graph invalid at 90°); in a
// box whose gap to the rectangle is smaller than a·L, DG-IDW drags the cells
// near the far field along and inverts them (measured: docs/dg-idw-length-scale.md).
#include "dgwarp/mesh/mesh.hpp"

namespace dgwarp {

struct RectBoxOptions {
    double rect_width = 2.0;    // rectangle, centred at the origin
    double rect_height = 1.0;
    double box_half_size = 20.0;  // box [-h, h]²
    int around = 78;             // nodes around each loop; a multiple of 2(w+h)/gcd so corners are nodes
    int layers = 30;             // node layers from the rectangle (1) to the box (layers)
    double growth = 1.2;         // ratio of successive layer thicknesses (clusters layers at the wall)
};

/// The structured O-grid between the rectangle and the box: 2D, quadrilaterals
/// oriented counter-clockwise, markers "rectangle" and "farfield". The default
/// options give 78 × 30 = 2,340 nodes and 2,262 cells. Throws MeshError when
/// the options cannot place the rectangle's corners on nodes.
Mesh make_rect_box(const RectBoxOptions& options = {});

}  // namespace dgwarp
