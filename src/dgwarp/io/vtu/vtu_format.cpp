// VTK XML unstructured grids (vtu.hpp), registered in mesh_format.hpp.
#include "dgwarp/io/mesh_format.hpp"
#include "dgwarp/io/vtu/vtu.hpp"

namespace dgwarp {

const MeshFormat vtu_format{
    "VTU", ".vtu", false, /*fields=*/true, false, false, nullptr, nullptr,
    [](const std::filesystem::path& path, const ReadOptions&, const ProgressFn& progress, MeshExtras*) {
        return read_vtu(path, progress);
    },
    [](const std::filesystem::path&, const Mesh& mesh, const WriteOptions&) { validate(mesh); },
    [](const std::filesystem::path& path, const Mesh& mesh, const MeshFields& fields, const WriteOptions&) {
        write_vtu(path, mesh, fields);
    },
};

}  // namespace dgwarp
