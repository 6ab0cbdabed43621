#pragma once
// Checks of a program's output files, made before its work starts: no output
// may be one of its inputs and every output must be writable, so that a long
// run does not fail (or destroy its input) at its end. The mesh formats' own
// outputs (an OpenFOAM case's files) are io/mesh_io.hpp's check_mesh_output.
#include <filesystem>
#include <vector>

namespace dgwarp {

/// Refuses `output` when it is one of `inputs` (UsageError): the same file,
/// also through symbolic or hard links or another spelling of its path
/// (std::filesystem::equivalent); and when it exists and cannot be replaced
/// (IoError: a folder, a device, a read-only file; check_replaceable).
void check_output(const std::filesystem::path& output, const std::vector<std::filesystem::path>& inputs);

/// check_output, and that files can be created in its folder (IoError with
/// the operating system's reason, check_folder_writable).
void check_output_file(const std::filesystem::path& output, const std::vector<std::filesystem::path>& inputs);

/// Throws IoError (check_folder_writable) unless files can be created in
/// `folder` or, when it does not exist yet, in the nearest folder above it
/// that exists.
void check_nearest_folder_writable(const std::filesystem::path& folder);

/// Creates the folder `folder` (and its parents) when missing and checks that
/// files can be created in it; IoError with the operating system's reason.
void make_output_folder(const std::filesystem::path& folder);

}  // namespace dgwarp
