#pragma once
// The markers an SU2 configuration file (CASE.cfg) names as symmetry planes
// (`MARKER_SYM= ( a, b )`): what an SU2 mesh file does not say. `dgwarp
// deform --su2-config CASE.cfg` makes them slide (docs/MOTION.md "Sliding by type").
#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

namespace dgwarp {

/// A marker an SU2 configuration names, and where.
struct Su2ConfigMarker {
    std::string name;
    std::size_t line = 0;  // 1-based line of its MARKER_SYM= in the file
};

/// The markers of `MARKER_SYM=` in the SU2 configuration file `path` (every
/// such line, in file order; `NONE` and `( )` give none). `%` starts a
/// comment; keys are case-insensitive, as SU2 reads them. Throws IoError when
/// the file cannot be read, ParseError (file, line) for a MARKER_SYM= value
/// that is not a list of names (an unclosed parenthesis).
std::vector<Su2ConfigMarker> su2_symmetry_markers(const std::filesystem::path& path);

}  // namespace dgwarp
