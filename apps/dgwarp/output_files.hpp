#pragma once
// Checks of a command's output files, made before its work starts: no output
// may be one of the command's inputs, each output's extension must say what is
// written, and every output must be writable, so that a long run does not fail
// (or destroy its input) at its end.
#include <filesystem>
#include <string>
#include <vector>

#include "dgwarp/motion/motion_spec.hpp"

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

/// The files reading the mesh `path` reads: an OpenFOAM case's polyMesh
/// files (points, faces, owner, neighbour, boundary), else `path` itself.
std::vector<std::filesystem::path> mesh_input_files(const std::filesystem::path& path);

/// check_output_file for a mesh output; for an OpenFOAM case folder, for each
/// file write_mesh writes there, and that the nearest existing folder on its
/// path is writable (the case folder may not exist yet).
void check_mesh_output(const std::filesystem::path& output, const std::vector<std::filesystem::path>& inputs);

/// Throws IoError (check_folder_writable) unless files can be created in
/// `folder` or, when it does not exist yet, in the nearest folder above it
/// that exists.
void check_nearest_folder_writable(const std::filesystem::path& folder);

/// Refuses `output` when it is one of `inputs` (usage error, exit 1): the same
/// file, also through symbolic or hard links or another spelling of its path
/// (std::filesystem::equivalent); and when it exists and cannot be replaced
/// (IoError, exit 2: a folder, a device, a read-only file; check_replaceable).
void check_output(const std::filesystem::path& output, const std::vector<std::filesystem::path>& inputs);

/// check_output, and that files can be created in its folder (IoError with
/// the operating system's reason, exit 2; check_folder_writable).
void check_output_file(const std::filesystem::path& output, const std::vector<std::filesystem::path>& inputs);

/// Creates the folder `folder` (and its parents) when missing and checks that
/// files can be created in it; IoError with the operating system's reason.
void make_output_folder(const std::filesystem::path& folder);

/// The files a motion file named (displacement, surface and node-motion files).
std::vector<std::filesystem::path> motion_files(const MotionSpec& spec);

}  // namespace dgwarp::cli
