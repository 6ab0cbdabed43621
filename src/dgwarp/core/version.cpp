#include "dgwarp/core/version.hpp"

namespace dgwarp {

// DGWARP_VERSION: set by src/dgwarp/CMakeLists.txt from the project's version.
std::string_view version() { return DGWARP_VERSION; }

}  // namespace dgwarp
