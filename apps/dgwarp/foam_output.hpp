#pragma once
// `dgwarp deform` into an OpenFOAM case folder: each frame's points go to a
// time folder (io/openfoam/openfoam_frames.hpp); --foam-time names it for a
// single frame. docs/OPENFOAM.md.
#include <string>
#include <vector>

#include "dgwarp/motion/motion_spec.hpp"

namespace dgwarp::cli {

/// The time folder of each frame: `given` (--foam-time; default "0") for a
/// single frame; for a series, openfoam_time_names of the frames' times.
/// Usage error (CLI::ValidationError) when `given` is neither "constant" nor
/// a number, or is given for a series.
std::vector<std::string> foam_time_names(const MotionSpec& spec, std::size_t frames, const std::string& given);

}  // namespace dgwarp::cli
