// Gmsh MSH 4.1 and 2.2 (gmsh.hpp), registered in mesh_format.hpp.
#include "dgwarp/io/gmsh/gmsh.hpp"
#include "dgwarp/io/mesh_format.hpp"

namespace dgwarp {

const MeshFormat gmsh_format{
    "Gmsh", ".msh", false, false, false, false, nullptr, nullptr,
    [](const std::filesystem::path& path, const ReadOptions&, const ProgressFn& progress, MeshExtras*) {
        return read_gmsh(path, progress);
    },
    [](const std::filesystem::path&, const Mesh& mesh, const WriteOptions&) { check_gmsh_writable(mesh); },
    [](const std::filesystem::path& path, const Mesh& mesh, const MeshFields&, const WriteOptions& options) {
        write_gmsh(path, mesh, options.gmsh_version);
    },
};

}  // namespace dgwarp
