#include "dgwarp/mesh/cell_type.hpp"

namespace dgwarp {

std::string_view cell_type_name(CellType t) {
    constexpr std::string_view names[] = {"vertex",      "line",       "triangle", "quadrilateral",
                                          "tetrahedron", "hexahedron", "prism",    "pyramid"};
    return names[static_cast<int>(t)];
}

int vtk_cell_id(CellType t) {
    constexpr int ids[] = {1, 3, 5, 9, 10, 12, 13, 14};
    return ids[static_cast<int>(t)];
}

std::optional<CellType> cell_type_from_vtk_id(int id) {
    for (CellType t : all_cell_types)
        if (vtk_cell_id(t) == id) return t;
    return std::nullopt;
}

}  // namespace dgwarp
