// PLACEHOLDER (being written): replaced by the real VTU writer.
#include "dgwarp/io/vtu.hpp"
#include "dgwarp/core/error.hpp"
namespace dgwarp {
void write_vtu(std::ostream&, const Mesh&, const MeshFields&) { throw FormatError("VTU writer not built yet"); }
void write_vtu(const std::filesystem::path&, const Mesh&, const MeshFields&) { throw FormatError("VTU writer not built yet"); }
}
