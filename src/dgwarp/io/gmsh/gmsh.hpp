#pragma once
// Gmsh MSH ASCII format, versions 4.1 and 2.2 (Gmsh manual, "MSH file format":
// https://gmsh.info/doc/texinfo/gmsh.html#MSH-file-format).
//
// Only linear elements are supported: lines, triangles, quadrangles,
// tetrahedra, hexahedra, prisms, pyramids (and points, which are skipped).
// Node order is converted between Gmsh's and dgwarp's (VTK's); only prisms
// differ (see gmsh_element_types.hpp).
#include <filesystem>
#include <ostream>
#include <string>

#include "dgwarp/core/progress.hpp"
#include "dgwarp/mesh/mesh.hpp"

namespace dgwarp {

/// Reads a Gmsh ASCII mesh, version 4.1 or 2.2 (detected from $MeshFormat).
///
/// - Dimension: the highest dimension of the elements present (2 or 3). A 2D
///   mesh must lie in the z = 0 plane; its points get 2 coordinates.
/// - Cells: every element of that dimension, in file order, whatever its
///   physical group.
/// - Markers: one per physical group of dimension dim - 1 (those named in
///   $PhysicalNames, given to an entity, or carried by an element), in tag
///   order, named from $PhysicalNames or "physical_<tag>". An element in
///   several groups is in each marker; elements of dimension dim - 1 in no
///   group are dropped; points (and lines of a 3D mesh) are ignored.
/// - Nodes: Gmsh tags (any positive values, sparse or not) become 0-based ids
///   in file order; mesh.points is num_points × dim, row-major.
/// - Sections other than $MeshFormat, $PhysicalNames, $Entities, $Nodes and
///   $Elements are skipped ($Periodic, $NodeData, $Comments, ...).
///
/// Throws IoError (cannot read), FormatError (binary file, another version,
/// partitioned mesh), ParseError (file, line, what was expected and found:
/// truncated or misplaced sections, wrong counts, bad numbers, unsupported
/// element types, undefined node tags) and MeshError (no 2D/3D elements, a 2D
/// mesh off the z = 0 plane, an inconsistent result).
/// `progress` (core/progress.hpp) gets the fraction of the file parsed.
Mesh read_gmsh(const std::filesystem::path& path, const ProgressFn& progress = {});

/// The same, from text in memory; `file_name` is used in error messages.
Mesh read_gmsh_text(const std::string& file_name, std::string content);

/// Writes `mesh` as Gmsh ASCII, version 41 (MSH 4.1) or 22 (MSH 2.2). Marker i
/// becomes the physical group of dimension dim - 1 with tag i + 1 and the
/// marker's name; the cells become the physical group "domain" of dimension
/// dim with tag n + 1 (n markers). Coordinates are written in shortest exact
/// form with 3 components (z = 0 in 2D), so read_gmsh gives back a mesh equal
/// to `mesh` (for a mesh with at least one cell). Throws FormatError for
/// another version, MeshError for an invalid mesh, a marker name with a double
/// quote or line break, or a marker of vertex elements.
void write_gmsh(std::ostream& out, const Mesh& mesh, int version = 41);

/// Throws the MeshError write_gmsh would throw about `mesh`, without writing.
void check_gmsh_writable(const Mesh& mesh);

/// Writes `mesh` as Gmsh ASCII to `path`, atomically (see write_file_atomically).
void write_gmsh(const std::filesystem::path& path, const Mesh& mesh, int version = 41);

}  // namespace dgwarp
