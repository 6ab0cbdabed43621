#include "dgwarp/mesh/cell_type.hpp"

#include <array>

namespace dgwarp {

std::string_view cell_type_name(CellType t) {
    constexpr std::string_view names[] = {"vertex",      "line",       "triangle", "quadrilateral",
                                          "tetrahedron", "hexahedron", "prism",    "pyramid",
                                          "polygon",     "polyhedron"};
    return names[static_cast<int>(t)];
}

int vtk_cell_id(CellType t) {
    constexpr int ids[] = {1, 3, 5, 9, 10, 12, 13, 14, 7, 42};
    return ids[static_cast<int>(t)];
}

std::optional<CellType> cell_type_from_vtk_id(int id) {
    // A table of the ids 0-255 (readers look up every element's id).
    static const auto table = [] {
        std::array<std::int16_t, 256> t{};
        t.fill(-1);
        for (CellType type : all_cell_types)
            if (vtk_cell_id(type) >= 0 && vtk_cell_id(type) < 256)
                t[static_cast<std::size_t>(vtk_cell_id(type))] = static_cast<std::int16_t>(type);
        return t;
    }();
    if (id >= 0 && id < 256) {
        const std::int16_t t = table[static_cast<std::size_t>(id)];
        return t < 0 ? std::nullopt : std::optional<CellType>(static_cast<CellType>(t));
    }
    for (CellType t : all_cell_types)
        if (vtk_cell_id(t) == id) return t;
    return std::nullopt;
}

}  // namespace dgwarp
