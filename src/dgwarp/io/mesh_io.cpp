#include "dgwarp/io/mesh_io.hpp"

#include <algorithm>
#include <cerrno>
#include <cctype>

#include "dgwarp/core/error.hpp"
#include "dgwarp/io/cgns.hpp"
#include "dgwarp/io/gmsh.hpp"
#include "dgwarp/io/marker_names.hpp"
#include "dgwarp/io/su2.hpp"
#include "dgwarp/io/vtu.hpp"

namespace dgwarp {

namespace {

std::string joined(const std::vector<std::string>& v) {
    std::string s;
    for (const auto& e : v) s += (s.empty() ? "" : ", ") + e;
    return s;
}

}  // namespace

std::string lower_case_extension(const std::filesystem::path& path) {
    std::string ext = path.extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
    return ext;
}

std::vector<std::string> readable_extensions() { return {".su2", ".msh", ".vtu", ".cgns"}; }
std::vector<std::string> writable_extensions() { return {".su2", ".msh", ".vtu", ".cgns"}; }

namespace {
bool has_mesh_extension(const std::filesystem::path& path) {
    const auto known = readable_extensions();
    return std::find(known.begin(), known.end(), lower_case_extension(path)) != known.end();
}
}  // namespace

bool reads_openfoam(const std::filesystem::path& path) { return !has_mesh_extension(path) && is_openfoam_input(path); }
bool writes_openfoam(const std::filesystem::path& path) { return !has_mesh_extension(path) && is_openfoam_output(path); }

namespace {
// Only SU2 files have zones: another zone asked of another format would be ignored.
void check_zone(const std::filesystem::path& path, const ReadOptions& options) {
    if (options.zone != 1 && (reads_openfoam(path) || lower_case_extension(path) != ".su2"))
        throw FormatError(path.string() + ": zone " + std::to_string(options.zone) +
                          " asked (--zone), but only SU2 files have several zones; this mesh is one zone");
}
}  // namespace

Mesh read_mesh(const std::filesystem::path& path, const ReadOptions& options, const ProgressFn& progress) {
    check_zone(path, options);
    if (reads_openfoam(path)) return read_openfoam(path, progress);
    const std::string ext = lower_case_extension(path);
    if (ext == ".su2") return read_su2(path, options.zone, progress);
    if (ext == ".msh") return read_gmsh(path, progress);
    if (ext == ".vtu") return read_vtu(path, progress);
    if (ext == ".cgns") {
        Mesh mesh = read_cgns(path);
        if (progress) progress(1.0);
        return mesh;
    }
    // No extension and nothing there (a case folder that is not there): say so, as for a
    // missing file of a known type, not "files of type ''".
    if (std::error_code ec; ext.empty() && !std::filesystem::exists(path, ec) && !ec)
        throw IoError(path.string(), "cannot open file for reading: No such file or directory (dgwarp reads " +
                                         joined(readable_extensions()) + " files and OpenFOAM case folders)",
                      ENOENT);
    throw FormatError(path.string() + ": cannot read files of type '" + ext + "'; dgwarp reads " +
                      joined(readable_extensions()) + " and OpenFOAM case folders");
}

Mesh read_mesh(const std::filesystem::path& path, const ReadOptions& options, const ProgressFn& progress,
               MeshExtras& extras) {
    extras = {};
    check_zone(path, options);
    if (reads_openfoam(path)) {
        OpenFoamSource source;
        Mesh mesh = read_openfoam(path, progress, &source);
        extras.openfoam = std::move(source);
        return mesh;
    }
    if (lower_case_extension(path) == ".cgns") {
        CgnsSource source;
        Mesh mesh = read_cgns(path, &source);
        if (progress) progress(1.0);
        extras.cgns = std::move(source);
        return mesh;
    }
    if (lower_case_extension(path) != ".su2") return read_mesh(path, options, progress);
    Su2Surroundings surroundings;
    Mesh mesh = read_su2(path, options.zone, progress, surroundings);
    extras.su2 = std::move(surroundings);
    return mesh;
}

namespace {

/// The OpenFOAM zones an output drops: every zone file for another format,
/// the face zones for an OpenFOAM case (its faces are numbered anew).
std::vector<std::string> dropped_zones(const MeshExtras& extras, const std::filesystem::path& path) {
    std::vector<std::string> dropped;
    if (!extras.openfoam) return dropped;
    for (const std::string& name : extras.openfoam->zone_files) {
        const std::string zone = name.substr(0, name.find('.'));
        if ((!writes_openfoam(path) || zone == "faceZones") &&
            std::find(dropped.begin(), dropped.end(), zone) == dropped.end())
            dropped.push_back(zone);
    }
    return dropped;
}

std::string joined_list(const std::vector<std::string>& items) {
    std::string list;
    for (const auto& d : items) list += (list.empty() ? "" : ", ") + d;
    return list;
}

}  // namespace

std::vector<std::string> dropped_extras(const MeshExtras& extras, const std::filesystem::path& path) {
    std::vector<std::string> dropped = dropped_zones(extras, path);
    if (extras.su2 && lower_case_extension(path) != ".su2")
        dropped.insert(dropped.end(), extras.su2->contents.begin(), extras.su2->contents.end());
    return dropped;
}

std::string dropped_extras_warning(const MeshExtras& extras, const std::string& input, const std::filesystem::path& output) {
    std::string text;
    if (const auto zones = dropped_zones(extras, output); !zones.empty())
        text = output.string() + " does not keep " + input + "'s " + joined_list(zones) +
               (writes_openfoam(output) ? " (OpenFOAM zones; the faces are numbered anew; its cell and point zones are kept)"
                                        : " (OpenFOAM zones; an OpenFOAM case output keeps the cell and point zones)");
    if (extras.su2 && lower_case_extension(output) != ".su2")
        text += (text.empty() ? "" : "; ") + output.string() + " holds the mesh only: " + input + " also has " +
                joined_list(extras.su2->contents) + " (an .su2 output keeps them)";
    return text;
}

void check_mesh_writable(const std::filesystem::path& path, const Mesh& mesh, const WriteOptions& options) {
    const std::string file = path.string();
    try {
        const std::string ext = lower_case_extension(path);
        if (writes_openfoam(path) || ext == ".vtu") {
            validate(mesh);
            if (writes_openfoam(path))
                for (const Marker& m : mesh.markers)
                    if (!is_openfoam_word(m.name))
                        throw MeshError("marker '" + m.name +
                                            "' cannot name an OpenFOAM patch (a patch name is one word: not empty, "
                                            "without blanks, quotes, slashes or any of ( ) { } ;); rename it",
                                        m.name);
        } else if (ext == ".su2") {
            check_su2_writable(mesh);
        } else if (ext == ".msh") {
            check_gmsh_writable(mesh);
        } else if (ext == ".cgns") {
            const CgnsSource* source = options.extras && options.extras->cgns ? &*options.extras->cgns : nullptr;
            if (!(source && source->num_points == mesh.num_points() && source->dim == mesh.dim))
                check_cgns_writable(path, mesh);
        }
    } catch (const MeshError& e) {
        if (std::string_view(e.what()).starts_with(file + ": ")) throw;
        throw MeshError(file + ": " + e.what(), e.marker(), e.index());
    }
}

bool writes_fields(const std::filesystem::path& path) {
    return !writes_openfoam(path) && lower_case_extension(path) == ".vtu";
}

void write_mesh(const std::filesystem::path& path, const Mesh& mesh, const MeshFields& fields,
                const WriteOptions& options) {
    if (writes_openfoam(path)) {
        OpenFoamWriteOptions foam;
        const OpenFoamSource* source = options.extras && options.extras->openfoam ? &*options.extras->openfoam : nullptr;
        foam.format = options.foam_format ? *options.foam_format : source ? source->points_format : foam::Format::ascii;
        foam.source = source;
        return write_openfoam(path, mesh, foam);
    }
    const std::string ext = lower_case_extension(path);
    if (ext == ".su2" && options.extras && options.extras->su2) return write_su2(path, mesh, *options.extras->su2);
    if (ext == ".su2") return write_su2(path, mesh);
    if (ext == ".msh") return write_gmsh(path, mesh, options.gmsh_version);
    if (ext == ".vtu") return write_vtu(path, mesh, fields);
    if (ext == ".cgns") {
        const CgnsSource* source = options.extras && options.extras->cgns ? &*options.extras->cgns : nullptr;
        if (source && source->num_points == mesh.num_points() && source->dim == mesh.dim)
            return write_cgns_points(path, *source, mesh.points);
        return write_cgns(path, mesh);
    }
    throw FormatError(path.string() + ": cannot write files of type '" + ext + "'; dgwarp writes " +
                      joined(writable_extensions()) + " and OpenFOAM case folders (a name ending in '/')");
}

}  // namespace dgwarp
