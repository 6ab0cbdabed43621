#include "dgwarp/cases/twisted_bar.hpp"

#include "dgwarp/cases/rect_box.hpp"

namespace dgwarp {

Mesh make_twisted_bar() {
    RectBoxOptions o;
    o.box_half_size = 10;
    o.cells = 87;
    o.rect_cells_x = 29;
    o.rect_cells_y = 9;
    Mesh mesh = make_rect_box(o);
    mesh.markers[0].name = "bar";  // make_rect_box names the inner loop "rectangle"
    return mesh;
}

}  // namespace dgwarp
