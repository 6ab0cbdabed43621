#pragma once
// Gmsh element type ids and node orders (internal to the Gmsh reader and writer).
//
// dgwarp stores VTK node order. For the linear elements dgwarp supports, Gmsh's
// order (Gmsh manual, "Node ordering") equals VTK's for lines, triangles,
// quadrangles, tetrahedra, hexahedra and pyramids. Prisms differ: Gmsh's
// triangle 0-1-2 turns counter-clockwise seen from the opposite triangle 3-4-5
// (reference nodes (0,0,-1), (1,0,-1), (0,1,-1), ...), VTK's wedge clockwise
// (its face 0-1-2 points out of the cell). Gmsh itself maps its prism to VTK
// with {0, 2, 1, 3, 5, 4} (MPrism::getVertexVTK), and the prisms of the SU2 test
// meshes (VTK order) have that orientation.
#include <optional>
#include <span>

#include "dgwarp/mesh/cell_type.hpp"

namespace dgwarp::msh {

/// The CellType of Gmsh element type `id`, or nullopt when dgwarp does not
/// support it (only linear elements: 1 line, 2 triangle, 3 quadrangle,
/// 4 tetrahedron, 5 hexahedron, 6 prism, 7 pyramid, 15 point).
std::optional<CellType> cell_type_from_gmsh_id(int id);

/// Gmsh element type id of `t` (inverse of cell_type_from_gmsh_id).
int gmsh_type_id(CellType t);

/// Node permutation between the two orders, nodes_per_cell(t) entries:
/// vtk_nodes[i] == gmsh_nodes[order[i]] for i in [0, nodes_per_cell(t)).
std::span<const int> gmsh_index_of_vtk_node(CellType t);

/// Human-readable list of the supported Gmsh type ids, for error messages.
const char* supported_gmsh_types_text();

}  // namespace dgwarp::msh
