// SU2 native ASCII (su2.hpp), registered in mesh_format.hpp.
#include "dgwarp/io/mesh_format.hpp"
#include "dgwarp/io/su2/su2.hpp"

namespace dgwarp {

const MeshFormat su2_format{
    "SU2", ".su2", /*zones=*/true, /*fields=*/false, /*keeps_su2_surroundings=*/true, /*keeps_openfoam_zones=*/false,
    nullptr, nullptr,
    [](const std::filesystem::path& path, const ReadOptions& options, const ProgressFn& progress, MeshExtras* extras) {
        if (!extras) return read_su2(path, options.zone, progress);
        Su2Surroundings surroundings;
        Mesh mesh = read_su2(path, options.zone, progress, surroundings);
        extras->su2 = std::move(surroundings);
        return mesh;
    },
    [](const std::filesystem::path&, const Mesh& mesh, const WriteOptions&) { check_su2_writable(mesh); },
    [](const std::filesystem::path& path, const Mesh& mesh, const MeshFields&, const WriteOptions& options) {
        if (options.extras && options.extras->su2) return write_su2(path, mesh, *options.extras->su2);
        write_su2(path, mesh);
    },
};

}  // namespace dgwarp
