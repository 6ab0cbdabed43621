#pragma once
// The mesh file formats, each registered once (its own *_format.cpp): how
// dgwarp knows its files, reads and writes them, and what of another file's
// extras it keeps. read_mesh, write_mesh, check_mesh_writable, writes_fields
// and dropped_extras (mesh_io.hpp) choose a format here; adding one is a
// *_format.cpp and a line of mesh_formats().
#include <filesystem>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "dgwarp/io/mesh_io.hpp"

namespace dgwarp {

struct MeshFormat {
    std::string_view name;       // "SU2", for messages
    std::string_view extension;  // ".su2" (lower case); "" for a format of folders (OpenFOAM)
    bool zones = false;          // its files hold several zones (ReadOptions::zone)
    bool fields = false;         // write keeps the MeshFields it is given
    bool keeps_su2_surroundings = false;  // write keeps an SU2 input's other zones, FFD boxes, ...
    bool keeps_openfoam_zones = false;    // write keeps an OpenFOAM input's cell and point zones
    /// A format of folders: whether `path` is one to read, or to write.
    bool (*is_input)(const std::filesystem::path&) = nullptr;
    bool (*is_output)(const std::filesystem::path&) = nullptr;
    /// Reads `path`; with `extras`, also what the file holds besides the mesh.
    Mesh (*read)(const std::filesystem::path& path, const ReadOptions& options, const ProgressFn& progress,
                 MeshExtras* extras) = nullptr;
    /// Throws the MeshError `write` would throw about `mesh` itself, writing nothing.
    void (*check_writable)(const std::filesystem::path& path, const Mesh& mesh, const WriteOptions& options) = nullptr;
    void (*write)(const std::filesystem::path& path, const Mesh& mesh, const MeshFields& fields,
                  const WriteOptions& options) = nullptr;
    /// The files `read` reads for `path` (nullptr: `path` itself), which no
    /// output may be (mesh_input_files).
    std::vector<std::filesystem::path> (*input_files)(const std::filesystem::path& path) = nullptr;
    /// The files `write` writes for `path` (nullptr: `path` itself), in
    /// folders it may make (check_mesh_output).
    std::vector<std::filesystem::path> (*output_files)(const std::filesystem::path& path) = nullptr;
};

extern const MeshFormat su2_format, gmsh_format, vtu_format, cgns_format, openfoam_format;

/// Every format, those with an extension first (a path with one of their
/// extensions is never taken as a folder).
std::span<const MeshFormat* const> mesh_formats();

/// The format read_mesh / write_mesh take `path` in, or nullptr.
const MeshFormat* format_to_read(const std::filesystem::path& path);
const MeshFormat* format_to_write(const std::filesystem::path& path);

}  // namespace dgwarp
