#pragma once
// The project's version (CMakeLists.txt's project(... VERSION ...)), one
// definition for the CLI's --version, Python's dgwarp.__version__ and the
// reports.
#include <string_view>

namespace dgwarp {

/// "MAJOR.MINOR.PATCH", e.g. "0.1.0".
std::string_view version();

}  // namespace dgwarp
