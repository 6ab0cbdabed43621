// CGNS (cgns.hpp), registered in mesh_format.hpp. A CGNS output of a CGNS
// input with the same points is a copy of the input with new coordinates.
#include "dgwarp/io/cgns/cgns.hpp"
#include "dgwarp/io/mesh_format.hpp"

namespace dgwarp {

namespace {

/// The CGNS input `mesh` is a deformed copy of, or nullptr.
const CgnsSource* cgns_source(const Mesh& mesh, const WriteOptions& options) {
    const CgnsSource* source = options.extras && options.extras->cgns ? &*options.extras->cgns : nullptr;
    return source && source->num_points == mesh.num_points() && source->dim == mesh.dim ? source : nullptr;
}

}  // namespace

const MeshFormat cgns_format{
    "CGNS", ".cgns", false, false, false, false, nullptr, nullptr,
    [](const std::filesystem::path& path, const ReadOptions&, const ProgressFn& progress, MeshExtras* extras) {
        CgnsSource source;
        Mesh mesh = read_cgns(path, extras ? &source : nullptr);
        if (progress) progress(1.0);
        if (extras) extras->cgns = std::move(source);
        return mesh;
    },
    [](const std::filesystem::path& path, const Mesh& mesh, const WriteOptions& options) {
        // A copy of the input keeps the input's names: nothing to check.
        if (!cgns_source(mesh, options)) check_cgns_writable(path, mesh);
    },
    [](const std::filesystem::path& path, const Mesh& mesh, const MeshFields&, const WriteOptions& options) {
        if (const CgnsSource* source = cgns_source(mesh, options)) return write_cgns_points(path, *source, mesh.points);
        write_cgns(path, mesh);
    },
};

}  // namespace dgwarp
