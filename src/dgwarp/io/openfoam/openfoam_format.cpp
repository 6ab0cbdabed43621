// OpenFOAM case and polyMesh folders (openfoam.hpp), registered in mesh_format.hpp.
#include "dgwarp/core/error.hpp"
#include "dgwarp/io/marker_names.hpp"
#include "dgwarp/io/mesh_format.hpp"
#include "dgwarp/io/openfoam/openfoam.hpp"

namespace dgwarp {

namespace {

/// The polyMesh files read_openfoam reads for `path`: a decomposed case's
/// processors' (with their addressing, and the points of the time read), or
/// the case's (its points perhaps a time folder's); `path` itself when it is
/// no case (reading it will say why).
std::vector<std::filesystem::path> openfoam_input_files(const std::filesystem::path& path) {
    std::vector<std::filesystem::path> processors;
    try {
        processors = openfoam_processor_meshes(path);
    } catch (const Error&) {
        return {path};
    }
    std::vector<std::filesystem::path> files;
    if (!processors.empty()) {
        const auto time = openfoam_decomposed_time(path);
        for (const auto& dir : processors) {
            for (const char* name : poly_mesh_file_names) files.push_back(dir / name);
            for (const char* name : processor_addressing_file_names) files.push_back(dir / name);
            if (time) files.push_back(dir.parent_path().parent_path() / time->time / "polyMesh" / "points");
        }
        return files;
    }
    std::filesystem::path dir;
    try {
        dir = find_poly_mesh(path);
    } catch (const Error&) {
        return {path};
    }
    for (const char* name : poly_mesh_file_names) files.push_back(dir / name);
    files.front() = openfoam_points_folder(path) / "points";  // a time folder's, maybe
    return files;
}

/// The polyMesh files write_openfoam writes for the case folder `path`.
std::vector<std::filesystem::path> openfoam_output_files(const std::filesystem::path& path) {
    const std::filesystem::path dir = openfoam_output_poly_mesh(path);
    std::vector<std::filesystem::path> files;
    for (const char* name : poly_mesh_file_names) files.push_back(dir / name);
    return files;
}

}  // namespace

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
    openfoam_input_files,
    openfoam_output_files,
};

}  // namespace dgwarp
