#pragma once
// Element types and their node counts. Node order within an element follows
// VTK's convention (which SU2 uses too); readers of other formats permute to it.
#include <cstdint>
#include <optional>
#include <string_view>

namespace dgwarp {

enum class CellType : std::uint8_t {
    vertex,         // 1 node (boundary element of a 1D marker; rare)
    line,           // 2 nodes: boundary element in 2D
    triangle,       // 3 nodes: cell in 2D, boundary element in 3D
    quadrilateral,  // 4 nodes, counter-clockwise
    tetrahedron,    // 4 nodes
    hexahedron,     // 8 nodes: bottom face 0-3, top face 4-7
    prism,          // 6 nodes (VTK wedge): triangle 0-1-2, triangle 3-4-5
    pyramid,        // 5 nodes: base quad 0-3, apex 4
};

inline constexpr CellType all_cell_types[] = {
    CellType::vertex,      CellType::line,       CellType::triangle, CellType::quadrilateral,
    CellType::tetrahedron, CellType::hexahedron, CellType::prism,    CellType::pyramid};

/// Number of nodes of an element of type t.
constexpr int nodes_per_cell(CellType t) {
    constexpr int n[] = {1, 2, 3, 4, 4, 8, 6, 5};
    return n[static_cast<int>(t)];
}

/// Topological dimension of t (0 for vertex, 1 for line, 2 for faces, 3 for solids).
constexpr int cell_dimension(CellType t) {
    constexpr int d[] = {0, 1, 2, 2, 3, 3, 3, 3};
    return d[static_cast<int>(t)];
}

/// Lower-case name ("triangle", "hexahedron", ...).
std::string_view cell_type_name(CellType t);

/// VTK cell type id (also SU2's element id): 1, 3, 5, 9, 10, 12, 13, 14.
int vtk_cell_id(CellType t);

/// The CellType for a VTK/SU2 id, or nullopt for an id dgwarp does not support.
std::optional<CellType> cell_type_from_vtk_id(int id);

}  // namespace dgwarp
