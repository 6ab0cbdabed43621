// PLACEHOLDER (being written): replaced by the real SU2 writer.
#include "dgwarp/io/su2.hpp"
#include "dgwarp/core/error.hpp"
namespace dgwarp {
void write_su2(std::ostream&, const Mesh&) { throw FormatError("SU2 writer not built yet"); }
void write_su2(const std::filesystem::path&, const Mesh&) { throw FormatError("SU2 writer not built yet"); }
}
