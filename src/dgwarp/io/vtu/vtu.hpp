#pragma once
// VTK XML unstructured grid (.vtu), for ParaView and back.
//
// What write_vtu writes: <VTKFile type="UnstructuredGrid" version="1.0"
// byte_order="LittleEndian" header_type="UInt64"> with, in <UnstructuredGrid>,
// the markers' <FieldData> (when the mesh has markers) and one Piece holding
// PointData, CellData, Points and Cells. Every array is format="binary", inline
// and uncompressed: its text is the base64 encoding (RFC 4648, one stream, no
// line breaks) of an 8-byte little-endian UInt64 byte count followed by that
// many bytes of little-endian values. Arrays:
//  - Points: Float64, 3 components (z = 0 for a 2D mesh);
//  - Cells: connectivity Int64 (0-based node ids, VTK node order as in Mesh;
//    a polyhedron's distinct nodes), offsets Int64 (end of each cell in
//    connectivity), types UInt8 (vtk_cell_id); with polyhedra also VTK's
//    faces and faceoffsets (Int64; see reading below);
//  - PointData / CellData: one Float64 DataArray per Field, with the field's
//    NumberOfComponents. ParaView shows 3-component arrays as vectors (glyphs,
//    Warp By Vector), so pass displacements with 3 components, z = 0 in 2D.
//  - FieldData, the markers (format of dgwarp's own; other programs ignore it):
//    DataArray UInt8 "dgwarp_marker_names" (the names' bytes, each name ended
//    by a 0 byte, in marker order; bytes rather than a String array, which
//    meshio cannot read; read_vtu takes either); DataArray Int64
//    "dgwarp_marker_sizes" (M element counts); DataArray UInt8
//    "dgwarp_marker_types" (the VTK id of every boundary element, marker after
//    marker); DataArray Int64 "dgwarp_marker_connectivity" (their node ids);
//    when a marker holds polygons, DataArray Int64 "dgwarp_marker_offsets"
//    (the end of each element in the connectivity).
// The markers are not cells of the grid: ParaView would draw each boundary
// element over the face of the cell it bounds, coloured by its own cell data
// (which a boundary element does not have), so the walls and the far field
// would show in the colour for NaN instead of the cells' quality.
//
// What read_vtu reads: what write_vtu writes, and what VTK, ParaView and
// meshio write for unstructured grids: DataArrays in ascii, binary (base64)
// or appended (raw or base64) format, header_type UInt32 or UInt64,
// LittleEndian or BigEndian, uncompressed or compressor="vtkZLibDataCompressor";
// any integer or float type; several Pieces (their points joined in order);
// the linear cell types (vertex, line, triangle, polygon, pixel, quad, tetra,
// voxel, hexahedron, wedge, pyramid) and polyhedra (VTK_POLYHEDRON, 42: the
// <Cells> arrays "faces", per polyhedron its face count then each face's node
// count and nodes, and "faceoffsets", the end of each cell's part of "faces"
// or -1; the faces are turned to point out of the cell, as VTK's files do not
// always have them). The mesh's dimension is the highest dimension
// of its cells (a 2D mesh must lie in the z = 0 plane); its cells are the
// cells of that dimension, in file order. Markers come from dgwarp's
// FieldData; without it, from meshio's "gmsh:physical" cell data (the cells
// of dimension dim - 1 grouped by tag, named from meshio's field data
// [tag, dim - 1] or "physical_<tag>"); other lower-dimension cells are
// dropped. Point and cell data are not read.
#include <filesystem>
#include <ostream>
#include <string>

#include "dgwarp/core/progress.hpp"
#include "dgwarp/io/mesh_io.hpp"
#include "dgwarp/mesh/mesh.hpp"

namespace dgwarp {

/// Writes the mesh's cells and markers with point and cell data fields.
/// `mesh.points` is num_points × dim, row-major; each point field holds
/// num_points × components values and each cell field cells.size() ×
/// components values, row-major. Field names are XML-escaped. Coordinates are
/// written as binary Float64, so read_vtu gives back a mesh equal to `mesh`
/// (for a mesh with at least one cell). Throws MeshError, before writing
/// anything, when the mesh is inconsistent (see validate), a marker name
/// holds a 0 byte, or a field has fewer than 1 component,
/// the wrong number of values or a name with a control character XML cannot
/// hold (the message names the field or marker).
void write_vtu(std::ostream& out, const Mesh& mesh, const MeshFields& fields = {});

/// Writes to `path` through write_file_atomically: on any error the file at
/// `path` is left as it was.
void write_vtu(const std::filesystem::path& path, const Mesh& mesh, const MeshFields& fields = {});

/// Reads a .vtu file (see above): dim, points (num_points × dim, row-major),
/// cells and markers. Throws IoError when the file cannot be read;
/// FormatError for another VTK file type or a compressor other than zlib;
/// ParseError (the file, the line of the element at fault, what was expected
/// and what was found; the byte offset too for appended raw data) for
/// malformed XML, missing or inconsistent attributes and arrays, undecodable
/// data, counts that do not match, unsupported cell types, node ids out of
/// range, non-finite coordinates; MeshError when the grid has no 2D or 3D
/// cells, a 2D grid leaves the z = 0 plane or the result fails validate().
/// `progress` (core/progress.hpp) gets the fraction of the file decoded.
Mesh read_vtu(const std::filesystem::path& path, const ProgressFn& progress = {});

/// The same, from the file's bytes in memory; `file_name` is used in error messages.
Mesh read_vtu_text(const std::string& file_name, std::string content);

}  // namespace dgwarp
