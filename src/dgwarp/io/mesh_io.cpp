#include "dgwarp/io/mesh_io.hpp"

#include <algorithm>
#include <cerrno>
#include <cctype>

#include "dgwarp/core/error.hpp"
#include "dgwarp/core/joined.hpp"
#include "dgwarp/core/output_checks.hpp"
#include "dgwarp/io/mesh_format.hpp"

namespace dgwarp {

std::string lower_case_extension(const std::filesystem::path& path) {
    std::string ext = path.extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
    return ext;
}

std::span<const MeshFormat* const> mesh_formats() {
    static const MeshFormat* const formats[] = {&su2_format, &gmsh_format, &vtu_format, &cgns_format, &openfoam_format};
    return formats;
}

namespace {

/// The format of `path`'s extension, or nullptr.
const MeshFormat* format_by_extension(const std::filesystem::path& path) {
    const std::string ext = lower_case_extension(path);
    for (const MeshFormat* f : mesh_formats())
        if (!f->extension.empty() && f->extension == ext) return f;
    return nullptr;
}

/// The format of folders that takes `path` (`output`: to write), or nullptr.
const MeshFormat* folder_format(const std::filesystem::path& path, bool output) {
    for (const MeshFormat* f : mesh_formats())
        if (f->extension.empty() && (output ? f->is_output(path) : f->is_input(path))) return f;
    return nullptr;
}

std::vector<std::string> extensions() {
    std::vector<std::string> list;
    for (const MeshFormat* f : mesh_formats())
        if (!f->extension.empty()) list.emplace_back(f->extension);
    return list;
}

}  // namespace

const MeshFormat* format_to_read(const std::filesystem::path& path) {
    if (const MeshFormat* f = format_by_extension(path)) return f;
    return folder_format(path, false);
}

const MeshFormat* format_to_write(const std::filesystem::path& path) {
    if (const MeshFormat* f = format_by_extension(path)) return f;
    return folder_format(path, true);
}

std::vector<std::string> readable_extensions() { return extensions(); }
std::vector<std::string> writable_extensions() { return extensions(); }

bool reads_openfoam(const std::filesystem::path& path) { return format_to_read(path) == &openfoam_format; }
bool writes_openfoam(const std::filesystem::path& path) { return format_to_write(path) == &openfoam_format; }

std::vector<std::filesystem::path> mesh_input_files(const std::filesystem::path& path) {
    const MeshFormat* format = format_to_read(path);
    return format && format->input_files ? format->input_files(path) : std::vector<std::filesystem::path>{path};
}

void check_mesh_output(const std::filesystem::path& output, const std::vector<std::filesystem::path>& inputs) {
    const MeshFormat* format = format_to_write(output);
    if (!format || !format->output_files) return check_output_file(output, inputs);
    const std::vector<std::filesystem::path> files = format->output_files(output);
    for (const auto& file : files) check_output(file, inputs);
    if (!files.empty()) check_nearest_folder_writable(files.front().parent_path());
}

namespace {

/// The format to read `path` in: a file of another type or a missing one is an error naming it.
const MeshFormat& reading_format(const std::filesystem::path& path, const ReadOptions& options) {
    const MeshFormat* f = format_to_read(path);
    const std::string ext = lower_case_extension(path);
    if (!f) {
        // No extension and nothing there (a case folder that is not there): say so, as for a
        // missing file of a known type, not "files of type ''".
        if (std::error_code ec; ext.empty() && !std::filesystem::exists(path, ec) && !ec)
            throw IoError(path.string(), "cannot open file for reading: No such file or directory (dgwarp reads " +
                                             joined(readable_extensions()) + " files and OpenFOAM case folders)",
                          ENOENT);
        throw FormatError(path.string() + ": cannot read files of type '" + ext + "'; dgwarp reads " +
                          joined(readable_extensions()) + " and OpenFOAM case folders");
    }
    // Another zone asked of a format without zones would be ignored.
    if (options.zone != 1 && !f->zones)
        throw FormatError(path.string() + ": zone " + std::to_string(options.zone) +
                          " asked (--zone), but only SU2 files have several zones; this mesh is one zone");
    return *f;
}

}  // namespace

Mesh read_mesh(const std::filesystem::path& path, const ReadOptions& options, const ProgressFn& progress) {
    return reading_format(path, options).read(path, options, progress, nullptr);
}

Mesh read_mesh(const std::filesystem::path& path, const ReadOptions& options, const ProgressFn& progress,
               MeshExtras& extras) {
    extras = {};
    return reading_format(path, options).read(path, options, progress, &extras);
}

namespace {

/// The OpenFOAM zones an output drops: every zone file for another format,
/// the face zones for an OpenFOAM case (its faces are numbered anew).
std::vector<std::string> dropped_zones(const MeshExtras& extras, const std::filesystem::path& path) {
    std::vector<std::string> dropped;
    if (!extras.openfoam) return dropped;
    const MeshFormat* f = format_to_write(path);
    const bool keeps = f && f->keeps_openfoam_zones;
    for (const std::string& name : extras.openfoam->zone_files) {
        const std::string zone = name.substr(0, name.find('.'));
        if ((!keeps || zone == "faceZones") && std::find(dropped.begin(), dropped.end(), zone) == dropped.end())
            dropped.push_back(zone);
    }
    return dropped;
}

/// Whether an output to `path` keeps an SU2 input's surroundings.
bool keeps_su2_surroundings(const std::filesystem::path& path) {
    const MeshFormat* f = format_to_write(path);
    return f && f->keeps_su2_surroundings;
}

}  // namespace

std::vector<std::string> dropped_extras(const MeshExtras& extras, const std::filesystem::path& path) {
    std::vector<std::string> dropped = dropped_zones(extras, path);
    if (extras.su2 && !keeps_su2_surroundings(path))
        dropped.insert(dropped.end(), extras.su2->contents.begin(), extras.su2->contents.end());
    return dropped;
}

std::string dropped_extras_warning(const MeshExtras& extras, const std::string& input, const std::filesystem::path& output) {
    std::string text;
    if (const auto zones = dropped_zones(extras, output); !zones.empty())
        text = output.string() + " does not keep " + input + "'s " + joined(zones) +
               (writes_openfoam(output) ? " (OpenFOAM zones; the faces are numbered anew; its cell and point zones are kept)"
                                        : " (OpenFOAM zones; an OpenFOAM case output keeps the cell and point zones)");
    if (extras.su2 && !keeps_su2_surroundings(output))
        text += (text.empty() ? "" : "; ") + output.string() + " holds the mesh only: " + input + " also has " +
                joined(extras.su2->contents) + " (an .su2 output keeps them)";
    return text;
}

void check_mesh_writable(const std::filesystem::path& path, const Mesh& mesh, const WriteOptions& options) {
    const std::string file = path.string();
    const MeshFormat* f = format_to_write(path);
    if (!f) return;  // write_mesh refuses the type
    try {
        f->check_writable(path, mesh, options);
    } catch (const MeshError& e) {
        if (std::string_view(e.what()).starts_with(file + ": ")) throw;
        throw MeshError(file + ": " + e.what(), e.marker(), e.index());
    }
}

bool writes_fields(const std::filesystem::path& path) {
    const MeshFormat* f = format_to_write(path);
    return f && f->fields;
}

void write_mesh(const std::filesystem::path& path, const Mesh& mesh, const MeshFields& fields,
                const WriteOptions& options) {
    const MeshFormat* f = format_to_write(path);
    if (!f)
        throw FormatError(path.string() + ": cannot write files of type '" + lower_case_extension(path) +
                          "'; dgwarp writes " + joined(writable_extensions()) +
                          " and OpenFOAM case folders (a name ending in '/')");
    f->write(path, mesh, fields, options);
}

}  // namespace dgwarp
