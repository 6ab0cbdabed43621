#pragma once
// CGNS files (.cgns, HDF5 or ADF, through Debian's libcgns). What is read and
// written, and the limits: docs/CGNS.md.
//
// Reading (read_cgns): the first base (CGNSBase_t; its cell dimension, 2 or
// 3, is the mesh's dim); its unstructured zones, one after the other. Point i
// of zone z is the mesh's point offset_z + i, except a vertex that a 1-to-1
// connectivity (GridConnectivity_t of type Abutting1to1, PointList and
// PointListDonor of vertices) joins to a vertex of an earlier zone: it is that
// vertex's point. Without such connectivity the zones' points stay separate
// (coincident points are not merged). Cells: the elements of the cell
// dimension of every element section (TETRA_4, PYRA_5, PENTA_6, HEXA_8;
// TRI_3, QUAD_4 in 2D; MIXED sections too), zone after zone, section after
// section, in file order, in VTK node order. Polyhedral sections: an NFACE_n
// element is a polyhedron of the NGON_n faces it names, each turned out of it
// (a negative face number: the face turned round, CGNS SIDS 7.3); NGON_n
// elements are faces in 3D (triangles, quadrilaterals, polygons), cells in 2D
// (polygons; of 2 nodes, edges). Markers: one per boundary
// condition (BC_t) name, or per family (FamilyName) when the BC has one; BCs
// of the same name in several zones form one marker. A BC's PointList or
// PointRange of face elements (GridLocation FaceCenter/EdgeCenter, or an
// ElementList/ElementRange) takes those elements of the zone's face sections;
// of vertices (GridLocation Vertex), the face elements of the zone whose nodes
// are all in the set, or when the zone has no face elements, the faces of its
// cells on the zone's boundary whose nodes are all in it. A face section no BC
// refers to is a marker of the section's name; a file with neither BCs nor
// face sections gets its cells' exterior faces as one marker, `exterior`.
//
// Writing (write_cgns): one base "Base", one unstructured zone "Zone", its
// coordinates in double precision, the cells in one section "Cells" (of the
// cells' type, or MIXED; NGON_n when they include polygons), each marker in a
// section of its own name followed by a BC_t of that name (BCTypeUserDefined,
// PointRange of those elements, GridLocation FaceCenter, or EdgeCenter in 2D).
// A mesh with polyhedra: every distinct face once in the NGON_n section
// "Faces" (the markers' first), every cell (polyhedra and fixed types alike)
// in the NFACE_n section "Cells" as signed face numbers, each marker a BC of
// its name with a PointList of its faces' numbers.
//
// Writing back (write_cgns_points): a copy of the file read, byte for byte but
// for the coordinates of its zones (GridCoordinates), written in the precision
// they had.
#include <filesystem>
#include <span>
#include <string>
#include <vector>

#include "dgwarp/mesh/mesh.hpp"

namespace dgwarp {

/// One zone of a CGNS file read: its name and the mesh's point of each of its vertices.
struct CgnsZone {
    std::string name;
    std::vector<NodeId> points;  // zone vertex i (0-based) is the mesh's point points[i]
};

/// What read_cgns keeps so that new coordinates can be written back into a copy of the file.
struct CgnsSource {
    std::filesystem::path file;  // the file read
    std::vector<CgnsZone> zones;  // the unstructured zones of base 1, in order
    std::size_t num_points = 0;   // the mesh's point count
    int dim = 3;                  // the mesh's dimension (the base's cell dimension)
    /// Per mesh marker: its BC's type name ("BCWall", "BCSymmetryPlane"; for a
    /// BC of type FamilySpecified, its family's FamilyBC_t type); "" for a
    /// face section no BC refers to. The first BC of the marker's name decides.
    std::vector<std::string> marker_types;
    /// The file has no BC and no face section: its cells' exterior faces (the
    /// faces of one cell, pointing out) are the one marker `exterior`.
    bool exterior_marker = false;
};

/// The name of that marker.
inline constexpr const char* exterior_marker_name = "exterior";

/// Reads base 1 of the CGNS file `path` (see above); fills `source` when given.
/// Throws IoError when the file cannot be opened or is not a CGNS file;
/// FormatError naming the file and the zone or section for what dgwarp does not
/// read (a structured zone, higher-order elements, NFACE_n cells in a 2D base,
/// another coordinate system); ParseError naming the file and the zone,
/// section or BC (line 0) when the content is inconsistent (a node, element or
/// face number out of range, a BC's elements that are not faces, an
/// ElementStartOffset that decreases, an NFACE_n cell whose faces do not close);
/// MeshError when the result fails validate().
Mesh read_cgns(const std::filesystem::path& path, CgnsSource* source = nullptr);

/// Writes `mesh` as a CGNS (HDF5) file, atomically (see above). Throws
/// MeshError before writing anything when the mesh is inconsistent (validate),
/// has no cells, or a marker name is not a CGNS name (1 to 32 characters,
/// no '/'), is used twice or is "Cells" (or "Faces", with polyhedra); IoError
/// when the file cannot be written.
void write_cgns(const std::filesystem::path& path, const Mesh& mesh);

/// Throws the MeshError write_cgns(path, mesh) would throw about `mesh`, without writing.
void check_cgns_writable(const std::filesystem::path& path, const Mesh& mesh);

/// Writes a copy of source.file to `path` with every zone's coordinates taken
/// from `points` (source.num_points × dim, row-major), atomically. Throws
/// MeshError when `points` does not hold source.num_points points of the
/// file's dimension; IoError when the source cannot be read or the copy written.
void write_cgns_points(const std::filesystem::path& path, const CgnsSource& source, std::span<const double> points);

}  // namespace dgwarp
