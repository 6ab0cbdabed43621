#include "dgwarp/io/gmsh/gmsh_element_types.hpp"

#include <iterator>

namespace dgwarp::msh {

namespace {
// Gmsh ids indexed by CellType (vertex, line, triangle, quadrilateral,
// tetrahedron, hexahedron, prism, pyramid; polygon and polyhedron: none, -1).
constexpr int gmsh_ids[] = {15, 1, 2, 3, 4, 5, 6, 7, -1, -1};
static_assert(std::size(gmsh_ids) == std::size(all_cell_types));

constexpr int identity[] = {0, 1, 2, 3, 4, 5, 6, 7};
constexpr int prism_order[] = {0, 2, 1, 3, 5, 4};
}  // namespace

std::optional<CellType> cell_type_from_gmsh_id(int id) {
    for (CellType t : all_cell_types)
        if (gmsh_type_id(t) == id && id >= 0) return t;
    return std::nullopt;
}

int gmsh_type_id(CellType t) { return gmsh_ids[static_cast<int>(t)]; }

std::span<const int> gmsh_index_of_vtk_node(CellType t) {
    const auto n = static_cast<std::size_t>(nodes_per_cell(t));
    if (t == CellType::prism) return {prism_order, n};
    return {identity, n};
}

const char* supported_gmsh_types_text() {
    return "a supported Gmsh element type (linear only: 1 line, 2 triangle, 3 quadrangle, "
           "4 tetrahedron, 5 hexahedron, 6 prism, 7 pyramid, 15 point)";
}

}  // namespace dgwarp::msh
