#pragma once
// Output file names and contents of deformed meshes.
#include <filesystem>
#include <string>
#include <vector>

#include "dgwarp/io/mesh_io.hpp"
#include "dgwarp/mesh/mesh.hpp"

namespace dgwarp::cli {

/// The file frame k of `frames` is written to: `out` itself for one frame,
/// else `out` with _0000, _0001, ... before the extension (at least 4 digits).
std::filesystem::path frame_path(const std::filesystem::path& out, std::size_t frame, std::size_t frames);

/// The frame files of an earlier, longer series that a series of `frames`
/// frames written to `out` leaves beside it (frame_path(out, k, ...) for
/// k = frames, frames + 1, ... while they exist; from k = 0 for one frame,
/// which is written to `out` itself). Empty when there are none.
std::vector<std::filesystem::path> stale_frames(const std::filesystem::path& out, std::size_t frames);

/// Point data "displacement" (3 components; z = 0 in 2D) and cell data
/// "quality" and, when `ratio` is not empty, "quality_ratio".
MeshFields deformation_fields(const Mesh& original, std::span<const double> new_points,
                              const std::vector<double>& quality, const std::vector<double>& ratio);

}  // namespace dgwarp::cli
