#pragma once
// `dgwarp bench --pictures`: PNGs of the 2D cases' meshes coloured by quality,
// as the paper's figures show them.
#include <filesystem>
#include <span>
#include <string>
#include <vector>

#include "dgwarp/mesh/mesh.hpp"

namespace dgwarp {

/// PNGs of the 2D `mesh` (case `case_name`, deformed from `original`)
/// coloured by `quality` (one value per cell) in `folder` (made when
/// missing): the whole mesh when `mesh` is `original` itself, and a close-up
/// of the moving body (for naca0012, of its trailing edge). Returns their
/// paths, relative to the folder of `markdown` when it is given. Nothing for
/// a 3D mesh. Throws IoError when a file cannot be written, and
/// std::filesystem::filesystem_error when `folder` cannot be made.
std::vector<std::string> write_bench_pictures(const std::filesystem::path& folder, const std::filesystem::path& markdown,
                                              const std::string& case_name, const Mesh& original, const Mesh& mesh,
                                              std::span<const double> quality, const std::string& stem,
                                              const std::string& caption);

}  // namespace dgwarp
