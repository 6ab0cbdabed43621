#include "dgwarp/cases/twisted_bar.hpp"

#include "dgwarp/cases/grid_with_hole.hpp"

namespace dgwarp {

Mesh make_twisted_bar() {
    GridWithHoleOptions o;
    o.box_half_size = 10;
    o.cells = 87;
    o.rect_cells_x = 29;
    o.rect_cells_y = 9;
    Mesh mesh = make_grid_with_hole(o);
    mesh.markers[0].name = "bar";  // the grid names the hole's loop "rectangle"
    return mesh;
}

}  // namespace dgwarp
