#pragma once
// VTK XML unstructured grid (.vtu) for ParaView. Write only.
//
// Layout: <VTKFile type="UnstructuredGrid" version="1.0" byte_order="LittleEndian"
// header_type="UInt64"> with one Piece holding PointData, CellData, Points and
// Cells. Every DataArray is format="binary", inline and uncompressed: its text
// is the base64 encoding (RFC 4648, one stream, no line breaks) of an 8-byte
// little-endian UInt64 byte count followed by that many bytes of little-endian
// values. Arrays:
//  - Points: Float64, 3 components (z = 0 for a 2D mesh);
//  - Cells: connectivity Int64 (0-based node ids, VTK node order as in Mesh),
//    offsets Int64 (end of each cell in connectivity), types UInt8 (vtk_cell_id);
//  - PointData / CellData: one Float64 DataArray per Field, with the field's
//    NumberOfComponents. ParaView shows 3-component arrays as vectors (glyphs,
//    Warp By Vector), so pass displacements with 3 components, z = 0 in 2D.
// Markers are not written: a .vtu holds only the volume cells.
#include <filesystem>
#include <ostream>

#include "dgwarp/io/mesh_io.hpp"
#include "dgwarp/mesh/mesh.hpp"

namespace dgwarp {

/// Writes the mesh's cells (not its markers) with point and cell data fields.
/// `mesh.points` is num_points × dim, row-major; each point field holds
/// num_points × components values and each cell field cells.size() ×
/// components values, row-major. Field names are XML-escaped. Throws
/// MeshError when the mesh is inconsistent (see validate) or when a field has
/// fewer than 1 component, the wrong number of values or a name with a
/// control character XML cannot hold (the message names the field).
void write_vtu(std::ostream& out, const Mesh& mesh, const MeshFields& fields = {});

/// Writes to `path` through write_file_atomically: on any error the file at
/// `path` is left as it was.
void write_vtu(const std::filesystem::path& path, const Mesh& mesh, const MeshFields& fields = {});

}  // namespace dgwarp
