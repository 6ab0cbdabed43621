#pragma once
// A deformation job's frames written: a mesh file per frame (the file's own
// format: VTU with the displacement and the cells' quality, SU2 keeping the
// input's other zones) or, for an OpenFOAM case folder, each frame's points
// in a time folder (io/openfoam/openfoam_frames.hpp). As the file's mesh: a 2D
// case's frames in 3D (job_inputs.hpp's output_points).
#include <filesystem>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "dgwarp/core/warning.hpp"
#include "dgwarp/io/mesh_io.hpp"
#include "dgwarp/io/openfoam/openfoam.hpp"
#include "dgwarp/job/job_inputs.hpp"
#include "dgwarp/mesh/mesh.hpp"

namespace dgwarp {

/// The file frame k of `frames` is written to: `out` itself for one frame,
/// else `out` with _0000, _0001, ... before the extension (at least 4 digits).
std::filesystem::path frame_path(const std::filesystem::path& out, std::size_t frame, std::size_t frames);

/// The frame files of an earlier, longer series that a series of `frames`
/// frames written to `out` leaves beside it (frame_path(out, k, ...) for
/// k = frames, frames + 1, ... while they exist; from k = 0 for one frame,
/// which is written to `out` itself). Empty when there are none.
std::vector<std::filesystem::path> stale_frames(const std::filesystem::path& out, std::size_t frames);

/// The warning about stale_frames(out, frames), if any: "FIRST ... LAST (N
/// files) are left from an earlier run, not written by this one (...)".
std::optional<Warning> stale_frames_warning(const std::filesystem::path& out, std::size_t frames);

/// The warning about an OpenFOAM case `case_path` in decomposePar's usual
/// layout (constant/polyMesh and processor folders) read and written whole:
/// its processor folders are not written (a parallel run reads them), unless
/// `processors_written`. None for another input.
std::optional<Warning> unread_processors_warning(const std::string& case_path, bool processors_written);

/// Point data "displacement" (3 components; z = 0 in 2D) and cell data
/// "quality" and, when `ratio` is not empty, "quality_ratio".
MeshFields deformation_fields(const Mesh& original, std::span<const double> new_points,
                              const std::vector<double>& quality, const std::vector<double>& ratio);

/// Where a job writes its frames, and what it has written so far. It views
/// the caller's time names and processors, which must outlive it.
struct FrameOutputs {
    std::filesystem::path out;  // a mesh file, or an OpenFOAM case folder
    std::size_t frames = 1;
    /// For an OpenFOAM case folder: each frame's time folder
    /// (openfoam_time_names); empty for a mesh file.
    std::span<const std::string> foam_times{};
    /// The processor folders beside the input's constant/polyMesh written
    /// with the whole case (read_processors_beside); empty for none.
    std::span<const OpenFoamProcessor> beside{};
    bool base_written = false;  // an OpenFOAM case's constant/polyMesh is there
    std::vector<double> lifted{};  // a 2D case's 3D points
};

/// Writes frame `frame`, whose points (of in.mesh) are `points` and whose
/// cells' quality is `quality`: to frame_path(o.out, frame, o.frames), with
/// deformation_fields where the format keeps fields and the input's extras
/// where it keeps them; or, for an OpenFOAM case folder, its points to its
/// time folder (the case's polyMesh first, once). Returns the file written
/// (OUT/processor*/<time>/polyMesh/points for a decomposed input). `points`
/// is as it was on return (write_output_mesh).
std::filesystem::path write_frame(JobInputs& in, FrameOutputs& o, std::size_t frame, std::vector<double>& points,
                                  const std::vector<double>& quality);

}  // namespace dgwarp
