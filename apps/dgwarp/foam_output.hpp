#pragma once
// `dgwarp deform` into an OpenFOAM case folder: the moved points of each frame
// go to a time folder's polyMesh/points (OpenFOAM reads them with
// constant/polyMesh's faces), or to constant/polyMesh/points
// (--foam-time constant); the case's constant/polyMesh is the input's (copied
// byte for byte unless the output is the input case, or written from a mesh
// of another format). A decomposed input: the same in each processorN folder,
// with the processor's own points. docs/OPENFOAM.md.
#include <filesystem>
#include <span>
#include <string>
#include <vector>

#include "deform_setup.hpp"
#include "dgwarp/motion/motion_spec.hpp"

namespace dgwarp::cli {

/// The time folder of each frame: `given` (default "0") for a single frame;
/// for a series, the frames' times (as OpenFOAM names them: 6 significant
/// digits, more when two would share a name) when they differ, else the
/// frame numbers 0, 1, .... Usage error (CLI::ValidationError) when `given`
/// is neither "constant" nor a number, or is given for a series.
std::vector<std::string> foam_time_names(const MotionSpec& spec, std::size_t frames, const std::string& given);

/// Checks, before the work, every file deforming into the case folder `out`
/// writes: the points of each time in `times` and, unless `out`'s
/// constant/polyMesh is the input's, the polyMesh files written there; none
/// may be an input (`inputs`), each must be replaceable, and files must be
/// creatable in the nearest existing folder.
/// `with_processors` (--foam-processors): also the processor folders beside
/// the input's constant/polyMesh, written as a decomposed input's.
void check_foam_outputs(const std::filesystem::path& out, const std::vector<std::string>& times,
                        const std::filesystem::path& input_mesh, const std::vector<std::filesystem::path>& inputs,
                        bool with_processors = false);

/// Writes out/constant/polyMesh for the moved points (once per output
/// folder, before its first points): a copy of the OpenFOAM input's polyMesh
/// files (none when it is the same folder), or the original mesh of another
/// format as a whole polyMesh; without the points when `time` puts them there.
/// `beside` (--foam-processors): the processor folders beside the input's
/// constant/polyMesh (read_processors_beside), written too.
void write_foam_base(const Inputs& in, const std::filesystem::path& out, const std::string& time,
                     const std::vector<OpenFoamProcessor>& beside = {});

/// Writes frame points `points` to out's points file for `time`, in the
/// format of the OpenFOAM input (ascii for another format); returns its path
/// (OUT/processor*/<time>/polyMesh/points for a decomposed input).
std::filesystem::path write_foam_points(const Inputs& in, const std::filesystem::path& out, const std::string& time,
                                        std::span<const double> points, const std::vector<OpenFoamProcessor>& beside = {});

}  // namespace dgwarp::cli
