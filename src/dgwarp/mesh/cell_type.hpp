#pragma once
// Element types and their node counts. Node order within an element follows
// VTK's convention (which SU2 uses too); readers of other formats permute to it.
#include <cstddef>
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
    polygon,        // 3 or more nodes in order round it: cell in 2D, boundary face in 3D
    polyhedron,     // its distinct nodes; its faces are kept beside them (ElementList::faces_of)
};

inline constexpr CellType all_cell_types[] = {
    CellType::vertex,      CellType::line,       CellType::triangle, CellType::quadrilateral,
    CellType::tetrahedron, CellType::hexahedron, CellType::prism,    CellType::pyramid,
    CellType::polygon,     CellType::polyhedron};

/// Number of nodes of an element of type t; 0 for polygon and polyhedron,
/// whose elements have any number.
constexpr int nodes_per_cell(CellType t) {
    constexpr int n[] = {1, 2, 3, 4, 4, 8, 6, 5, 0, 0};
    return n[static_cast<int>(t)];
}

/// Topological dimension of t (0 for vertex, 1 for line, 2 for faces, 3 for solids).
constexpr int cell_dimension(CellType t) {
    constexpr int d[] = {0, 1, 2, 2, 3, 3, 3, 3, 2, 3};
    return d[static_cast<int>(t)];
}

/// Whether elements of type t have any number of nodes (polygon, polyhedron).
constexpr bool has_any_node_count(CellType t) { return nodes_per_cell(t) == 0; }

/// The type of a face (of a 3D mesh) or 2D cell of n >= 3 nodes in order round it.
constexpr CellType polygon_type(std::size_t n) {
    return n == 3 ? CellType::triangle : n == 4 ? CellType::quadrilateral : CellType::polygon;
}

/// Lower-case name ("triangle", "hexahedron", ...).
std::string_view cell_type_name(CellType t);

/// VTK cell type id (also SU2's element id for the fixed types): 1, 3, 5, 9,
/// 10, 12, 13, 14; polygon 7, polyhedron 42.
int vtk_cell_id(CellType t);

/// The CellType for a VTK/SU2 id, or nullopt for an id dgwarp does not support.
std::optional<CellType> cell_type_from_vtk_id(int id);

}  // namespace dgwarp
