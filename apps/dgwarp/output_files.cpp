#include "output_files.hpp"

#include <CLI/CLI.hpp>
#include <algorithm>
#include <variant>

#include "dgwarp/core/atomic_write.hpp"
#include "dgwarp/core/error.hpp"
#include "dgwarp/io/mesh_io.hpp"

namespace dgwarp::cli {

namespace {

void add_table_source(std::vector<std::filesystem::path>& files, const std::string& source) {
    if (!source.empty() && std::find(files.begin(), files.end(), source) == files.end()) files.emplace_back(source);
}

void add_marker_files(std::vector<std::filesystem::path>& files, const MarkerMotion& motion) {
    if (const auto* d = std::get_if<PrescribedDisplacements>(&motion)) add_table_source(files, d->displacements.source);
    if (const auto* p = std::get_if<PrescribedPositions>(&motion)) add_table_source(files, p->positions.source);
    if (const auto* n = std::get_if<PrescribedNodeMotions>(&motion)) add_table_source(files, n->motions.source);
}

}  // namespace

void require_extension(const std::string& flag, const std::filesystem::path& output,
                       const std::vector<std::string>& extensions, const std::string& what) {
    const std::string ext = lower_case_extension(output);
    if (std::find(extensions.begin(), extensions.end(), ext) != extensions.end()) return;
    std::string list;
    for (const auto& e : extensions) list += (list.empty() ? "" : ", ") + e;
    throw CLI::ValidationError(flag, output.string() + ": this command writes " + what + ", so the name must end in " +
                                         list + (ext.empty() ? std::string(" (it has no extension)")
                                                             : " (not " + output.extension().string() + ")"));
}

void require_mesh_extension(const std::string& flag, const std::filesystem::path& output) {
    if (output.empty())
        throw CLI::ValidationError(flag, "the output name is empty: give a mesh file (" +
                                             [] {
                                                 std::string list;
                                                 for (const auto& e : writable_extensions())
                                                     list += (list.empty() ? "" : ", ") + e;
                                                 return list;
                                             }() +
                                             ") or an OpenFOAM case folder");
    if (writes_openfoam(output)) {
        // A name without a mesh extension is an OpenFOAM case folder; an existing file
        // (such as /dev/full) made that "cannot write files into this folder: Not a directory".
        std::error_code ec;
        if (std::filesystem::exists(output, ec) && !std::filesystem::is_directory(output, ec))
            throw CLI::ValidationError(flag, output.string() +
                                                 " is a file without a mesh extension: such a name is an OpenFOAM "
                                                 "case folder; name the output with the format's extension");
        return;
    }
    require_extension(flag, output, writable_extensions(),
                      "a mesh (the format is chosen by the extension; an OpenFOAM case is a folder, a name ending "
                      "in '/')");
}

std::vector<std::filesystem::path> mesh_input_files(const std::filesystem::path& path) {
    if (!reads_openfoam(path)) return {path};
    std::vector<std::filesystem::path> processors;
    try {
        processors = openfoam_processor_meshes(path);
    } catch (const Error&) {
        return {path};  // reading it will say why
    }
    if (!processors.empty()) {
        std::vector<std::filesystem::path> files;
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
        return {path};  // reading it will say why
    }
    std::vector<std::filesystem::path> files;
    for (const char* name : poly_mesh_file_names) files.push_back(dir / name);
    files.front() = openfoam_points_folder(path) / "points";  // a time folder's, maybe
    return files;
}

void check_nearest_folder_writable(const std::filesystem::path& folder) {
    std::filesystem::path p = folder;
    std::error_code ec;
    while (!p.empty() && !std::filesystem::exists(p, ec) && p.has_parent_path() && p.parent_path() != p)
        p = p.parent_path();
    if (!p.empty() && !std::filesystem::exists(p, ec)) p.clear();
    check_folder_writable(p);
}

void check_mesh_output(const std::filesystem::path& output, const std::vector<std::filesystem::path>& inputs) {
    if (!writes_openfoam(output)) return check_output_file(output, inputs);
    const std::filesystem::path dir = openfoam_output_poly_mesh(output);
    for (const char* name : poly_mesh_file_names) check_output(dir / name, inputs);
    check_nearest_folder_writable(dir);
}

void check_output(const std::filesystem::path& output, const std::vector<std::filesystem::path>& inputs) {
    std::error_code ec;
    if (std::filesystem::exists(output, ec)) {
        for (const auto& in : inputs)
            if (std::filesystem::equivalent(output, in, ec))
                throw CLI::ValidationError(output.string() + " is " +
                                           (output == in ? std::string("an input of this command")
                                                         : "the same file as the input " + in.string()) +
                                           ": it would be overwritten; write the output to another name");
        check_replaceable(output);
    }
}

void check_output_file(const std::filesystem::path& output, const std::vector<std::filesystem::path>& inputs) {
    check_output(output, inputs);
    check_folder_writable(output.parent_path());
}

void make_output_folder(const std::filesystem::path& folder) {
    std::error_code ec;
    std::filesystem::create_directories(folder, ec);
    if (ec) throw IoError(folder.string(), "cannot create this folder: " + ec.message());
    check_folder_writable(folder);
}

std::vector<std::filesystem::path> motion_files(const MotionSpec& spec) {
    std::vector<std::filesystem::path> files;
    add_marker_files(files, spec.default_motion);
    for (const MotionFrame& frame : spec.frames)
        for (const auto& [marker, motion] : frame.markers) add_marker_files(files, motion);
    return files;
}

}  // namespace dgwarp::cli
