#pragma once
// The paper's first test case (section 3.1, Fig. 8): a rectangle in a square
// box, meshed with structured quadrilaterals (an O-grid, 2,340 nodes by default).
#include "dgwarp/mesh/mesh.hpp"

namespace dgwarp {

struct RectBoxOptions {
    double rect_width = 2.0;    // rectangle, centred at the origin
    double rect_height = 1.0;
    double box_half_size = 6.0;  // box [-h, h]²
    int around = 78;             // nodes around each loop; a multiple of 2(w+h)/gcd so corners are nodes
    int layers = 30;             // node layers from the rectangle (1) to the box (layers)
    double growth = 1.12;        // ratio of successive layer thicknesses (clusters layers at the wall)
};

/// The structured O-grid between the rectangle and the box: 2D, quadrilaterals
/// oriented counter-clockwise, markers "rectangle" and "farfield". The default
/// options give 78 × 30 = 2,340 nodes and 2,262 cells. Throws MeshError when
/// the options cannot place the rectangle's corners on nodes.
Mesh make_rect_box(const RectBoxOptions& options = {});

}  // namespace dgwarp
