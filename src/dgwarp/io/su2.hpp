#pragma once
// SU2 native ASCII mesh format (https://su2code.github.io/docs_v7/Mesh-File/).
#include <filesystem>
#include <ostream>
#include <string>

#include "dgwarp/mesh/mesh.hpp"

namespace dgwarp {

/// Reads an SU2 ASCII mesh. `zone` selects the zone (IZONE, 1-based) of a
/// multi-zone file (NZONE=); single-zone files have only zone 1. FFD sections
/// and other trailing keywords are skipped. Throws IoError, ParseError (file,
/// line, what was expected), MeshError.
Mesh read_su2(const std::filesystem::path& path, int zone = 1);

/// The same, from text in memory; `file_name` is used in error messages.
Mesh read_su2_text(const std::string& file_name, std::string content, int zone = 1);

/// Writes `mesh` as SU2 ASCII to `out` (numbers in shortest exact form, so
/// reading it back gives the same mesh).
void write_su2(std::ostream& out, const Mesh& mesh);

/// Writes `mesh` as SU2 ASCII to `path`, atomically.
void write_su2(const std::filesystem::path& path, const Mesh& mesh);

}  // namespace dgwarp
