#pragma once
// The paper's third test case (section 4, Fig. 18): a bar in a box, meshed
// with structured quadrilaterals, 7,520 nodes and 7,308 cells.
#include "dgwarp/mesh/mesh.hpp"

namespace dgwarp {

/// A uniform Cartesian grid of the 20 × 20 box [-10, 10]² (87 cells a side)
/// with the bar (29 × 9 cells, 6.67 × 2.07, centred at the origin) cut out:
/// (make_grid_with_hole), which gives exactly the paper's 88² -
/// 28·8 = 7,520 nodes and 87² - 29·9 = 7,308 cells (the paper gives only the
/// counts and a figure; they fix the grid: N - F = half the boundary nodes).
/// Markers "bar" and "farfield".
Mesh make_twisted_bar();

}  // namespace dgwarp
