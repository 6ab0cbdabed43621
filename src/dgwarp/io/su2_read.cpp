// PLACEHOLDER (being written): replaced by the real SU2 reader.
#include "dgwarp/io/su2.hpp"
#include "dgwarp/core/error.hpp"
namespace dgwarp {
Mesh read_su2(const std::filesystem::path& path, int) { throw FormatError(path.string() + ": SU2 reader not built yet"); }
Mesh read_su2_text(const std::string& f, std::string, int) { throw FormatError(f + ": SU2 reader not built yet"); }
}
