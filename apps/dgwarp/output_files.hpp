#pragma once
// The names of a command's output files, checked before its work starts: each
// output's extension must say what is written. That no output is an input and
// that every output is writable: core/output_checks.hpp and io/mesh_io.hpp's
// check_mesh_output.
#include <filesystem>
#include <string>
#include <vector>

#include "dgwarp/core/output_checks.hpp"
#include "dgwarp/io/mesh_io.hpp"

namespace dgwarp::cli {

/// Refuses (usage error, exit 1) `output` (given by `flag`) when its
/// extension, compared without case, is not one of `extensions`; `what` says
/// what the command writes ("a plan file").
void require_extension(const std::string& flag, const std::filesystem::path& output,
                       const std::vector<std::string>& extensions, const std::string& what);

/// require_extension for a mesh output: .su2, .msh, .vtu or .cgns (writable_extensions()),
/// or an OpenFOAM case folder (writes_openfoam: a folder, a name ending in '/'
/// or without extension).
void require_mesh_extension(const std::string& flag, const std::filesystem::path& output);

}  // namespace dgwarp::cli
