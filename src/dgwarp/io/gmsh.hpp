#pragma once
// Gmsh MSH ASCII format, versions 4.1 and 2.2 (https://gmsh.info/doc/texinfo/gmsh.html#MSH-file-format).
#include <filesystem>
#include <ostream>
#include <string>

#include "dgwarp/mesh/mesh.hpp"

namespace dgwarp {

/// Reads a Gmsh ASCII mesh, version 4.1 or 2.2 (detected from $MeshFormat).
/// Elements of the mesh's top dimension become cells; elements one dimension
/// lower that belong to a physical group become the boundary elements of a
/// marker named after the group ("physical_<tag>" when it has no name).
/// Node tags are renumbered to 0-based ids in file order. Throws IoError,
/// ParseError (file, line, what was expected), MeshError, FormatError (binary).
Mesh read_gmsh(const std::filesystem::path& path);

/// The same, from text in memory; `file_name` is used in error messages.
Mesh read_gmsh_text(const std::string& file_name, std::string content);

/// Writes `mesh` as Gmsh ASCII, version 41 (4.1) or 22 (2.2); each marker
/// becomes a named physical group, the cells one physical group "domain".
void write_gmsh(std::ostream& out, const Mesh& mesh, int version = 41);

/// Writes `mesh` as Gmsh ASCII to `path`, atomically.
void write_gmsh(const std::filesystem::path& path, const Mesh& mesh, int version = 41);

}  // namespace dgwarp
