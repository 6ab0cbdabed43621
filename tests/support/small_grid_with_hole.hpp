#pragma once
// A small grid with a hole (make_grid_with_hole: 15 × 15 cells, a 5 × 3 hole,
// markers "rectangle" and "farfield"), for tests of whole runs that must stay fast.
#include "dgwarp/cases/grid_with_hole.hpp"

namespace dgwarp::test {

inline Mesh small_grid_with_hole() {
    GridWithHoleOptions o;
    o.cells = 15;
    o.rect_cells_x = 5;
    o.rect_cells_y = 3;
    return make_grid_with_hole(o);
}

}  // namespace dgwarp::test
