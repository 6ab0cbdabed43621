// OpenFOAM case and polyMesh folders (openfoam.hpp), registered in mesh_format.hpp.
#include "dgwarp/core/error.hpp"
#include "dgwarp/io/marker_names.hpp"
#include "dgwarp/io/mesh_format.hpp"
#include "dgwarp/io/openfoam/openfoam.hpp"

namespace dgwarp {

const MeshFormat openfoam_format{
    "OpenFOAM", "", false, false, false, /*keeps_openfoam_zones=*/true, is_openfoam_input, is_openfoam_output,
    [](const std::filesystem::path& path, const ReadOptions&, const ProgressFn& progress, MeshExtras* extras) {
        if (!extras) return read_openfoam(path, progress);
        OpenFoamSource source;
        Mesh mesh = read_openfoam(path, progress, &source);
        extras->openfoam = std::move(source);
        return mesh;
    },
    [](const std::filesystem::path&, const Mesh& mesh, const WriteOptions&) {
        validate(mesh);
        for (const Marker& m : mesh.markers)
            if (!is_openfoam_word(m.name))
                throw MeshError("marker '" + m.name +
                                    "' cannot name an OpenFOAM patch (a patch name is one word: not empty, without "
                                    "blanks, quotes, slashes or any of ( ) { } ;); rename it",
                                m.name);
    },
    [](const std::filesystem::path& path, const Mesh& mesh, const MeshFields&, const WriteOptions& options) {
        OpenFoamWriteOptions foam;
        const OpenFoamSource* source = options.extras && options.extras->openfoam ? &*options.extras->openfoam : nullptr;
        foam.format = options.foam_format ? *options.foam_format : source ? source->points_format : foam::Format::ascii;
        foam.source = source;
        write_openfoam(path, mesh, foam);
    },
};

}  // namespace dgwarp
