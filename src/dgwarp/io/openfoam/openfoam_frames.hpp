#pragma once
// A run's frames into an OpenFOAM case folder: the moved points of each frame
// go to a time folder's polyMesh/points (OpenFOAM reads them with
// constant/polyMesh's faces), or to constant/polyMesh/points (time
// "constant"); the case's constant/polyMesh is the input's (copied byte for
// byte unless the output is the input case, or written from a mesh of another
// format). A decomposed input: the same in each processorN folder, with the
// processor's own points. docs/OPENFOAM.md.
//
//   const auto times = openfoam_time_names(frame_times);
//   check_openfoam_frame_outputs(out, times, input, inputs);   // before the work
//   write_openfoam_frame_base(out, times[0], mesh, extras);     // once, before the first points
//   for each frame k: write_openfoam_frame_points(out, times[k], points_k, extras);
#include <filesystem>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "dgwarp/io/mesh_io.hpp"
#include "dgwarp/io/openfoam/openfoam.hpp"
#include "dgwarp/motion/motion_spec.hpp"

namespace dgwarp {

/// The time folder of each frame at `times`: "0" for a single frame; else
/// the times as OpenFOAM names them (6 significant digits, more when two
/// would share a name) when they differ, else the frame numbers 0, 1, ....
std::vector<std::string> openfoam_time_names(std::span<const double> times);

/// openfoam_time_names of the times of `spec`'s frames (frame_time).
std::vector<std::string> openfoam_frame_time_names(const MotionSpec& spec);

/// Whether `name` can name a frame's time folder: "constant" or a number
/// (0, 0.001, 1e-05), as the C locale reads it.
bool is_openfoam_time_name(std::string_view name);

/// Checks, before the work, every file writing frames into the case folder
/// `out` writes: the points of each time in `times` and, unless `out`'s
/// constant/polyMesh is the input's, the polyMesh files written there; none
/// may be an input (`inputs`), each must be replaceable, and files must be
/// creatable in the nearest existing folder (check_output,
/// check_nearest_folder_writable). `input_mesh`: the mesh read (a path
/// read_mesh takes). `with_processors`: also the processor folders beside the
/// input's constant/polyMesh (openfoam_unread_processor_folders), written as
/// a decomposed input's.
void check_openfoam_frame_outputs(const std::filesystem::path& out, const std::vector<std::string>& times,
                                  const std::filesystem::path& input_mesh,
                                  const std::vector<std::filesystem::path>& inputs, bool with_processors = false);

/// Writes out/constant/polyMesh for the moved points (once per output
/// folder, before its first points): a copy of the OpenFOAM input's polyMesh
/// files (`extras.openfoam`; none when it is the same folder), or `original`
/// (a mesh of another format) as a whole polyMesh; without the points when
/// `time` puts them there. `beside`: processor folders beside the input's
/// constant/polyMesh (read_processors_beside), written too.
void write_openfoam_frame_base(const std::filesystem::path& out, const std::string& time, const Mesh& original,
                               const MeshExtras& extras, std::span<const OpenFoamProcessor> beside = {});

/// Writes a frame's `points` to out's points file for `time`, in the format
/// of the OpenFOAM input (ascii for another format); returns its path
/// (OUT/processor*/<time>/polyMesh/points for a decomposed input).
std::filesystem::path write_openfoam_frame_points(const std::filesystem::path& out, const std::string& time,
                                                  std::span<const double> points, const MeshExtras& extras,
                                                  std::span<const OpenFoamProcessor> beside = {});

}  // namespace dgwarp
