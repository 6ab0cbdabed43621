#include "output_files.hpp"

#include <CLI/CLI.hpp>
#include <algorithm>

namespace dgwarp::cli {

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

}  // namespace dgwarp::cli
