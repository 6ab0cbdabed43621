#pragma once
// A deformation job's inputs from files, as `dgwarp deform` and `dgwarp
// prepare` take them: the mesh read (with what its file holds besides),
// the motion, the markers that slide or couple by their file's type, a 2D
// case stored as 3D deformed as its 2D mesh, the boundary resolved, and the
// original cells each frame is judged against; and the outputs written as
// the file's mesh (a 2D case's 3D points).
//
//   JobInputs in;
//   in.spec = read_motion_file(motion);
//   in.mesh = read_mesh(mesh, {zone}, progress, in.extras);
//   classify_inputs(in, {});
//   measure_original_cells(in, [&] { plan = prepare_for_frames(...); });
#include <filesystem>
#include <functional>
#include <optional>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "dgwarp/io/marker_names.hpp"
#include "dgwarp/io/mesh_io.hpp"
#include "dgwarp/mesh/planar_case.hpp"
#include "dgwarp/motion/resolve_motion.hpp"
#include "dgwarp/run/original_cells.hpp"

namespace dgwarp {

/// The mesh, the motion and the boundary, read and checked once.
struct JobInputs {
    /// The mesh deformed: the file's, or the 2D mesh of a 2D case stored as 3D (`planar`).
    Mesh mesh;
    MeshExtras extras;  // what the mesh file holds besides the mesh (SU2: other zones, FFD boxes)
    /// The motion, in `mesh`'s terms: markers that slide by their type added
    /// (`sliding_by_type`); for a 2D case, in its planes (motion/planar_motion.hpp).
    MotionSpec spec;
    std::vector<std::string> sliding_by_type;
    /// The OpenFOAM cyclic patch pairs coupled because of their type (TypedMotion::coupled).
    std::vector<std::pair<std::string, std::string>> coupled_by_type;
    /// A 2D case stored as 3D (an OpenFOAM 2D case): `mesh` is its 2D mesh,
    /// `file_mesh` the mesh read, which the outputs are (lift_points).
    std::optional<PlanarCase> planar;
    Mesh file_mesh;
    /// Empty patches that slide but make no 2D case: why (they slide in 3D).
    std::string not_planar;
    /// Markers renamed because the output's format cannot hold their names
    /// (InputSettings::writable_for), in the mesh and the motion.
    std::vector<MarkerRename> renamed_for_output;
    ResolvedBoundary boundary;
    /// The original cells every frame is judged against (run/original_cells.hpp):
    /// a cell flipped in the input counts as inverted before and after.
    OriginalCells original;
    double read_seconds = 0, resolve_seconds = 0, quality_seconds = 0;
};

/// What classify_inputs needs to know of the files.
struct InputSettings {
    /// An SU2 configuration whose MARKER_SYM markers slide ("" for none).
    std::string su2_config{};
    /// The output the job writes: marker names its format cannot hold are
    /// made into names it can (make_marker_names_writable), in the mesh and
    /// the motion alike, with a warning; "" for none.
    std::string writable_for{};
    /// How the caller names a marker otherwise, for those warnings' advice
    /// ("--rename-marker": "(--rename-marker 'a b=NEW' names it otherwise)"); "" for none.
    std::string rename_option{};
};

/// Classifies `in.mesh` and `in.spec` (read): marker names made writable,
/// markers that slide or couple by their type (apply_marker_types, with the
/// SU2 configuration's MARKER_SYM), a 2D case made 2D, and the boundary
/// resolved (every check of resolve_boundary), with the warnings a user
/// needs in in.boundary.warnings. MeshError names a MARKER_SYM marker the
/// mesh has not (the configuration's file and line).
void classify_inputs(JobInputs& in, const InputSettings& settings);

/// Calls work() (a method's prepare: mostly serial) with the original
/// mesh's orientation and quality measured beside it on a thread of its own
/// (measure_original_beside), then keeps them in `in` (in.original,
/// in.quality_seconds: the measure's own time, which overlaps work's) with
/// warn_already_inverted's warning. work() must not read in.original nor
/// in.boundary.warnings.
void measure_original_cells(JobInputs& in, const std::function<void()>& work);

/// Adds the boundary warning about the cells already inverted or degenerate
/// in the input (in.original.summary, its worst cell named), if any.
void warn_already_inverted(JobInputs& in);

/// The mesh outputs are written as: the file's (in.file_mesh for a 2D case).
const Mesh& output_mesh(const JobInputs& in);

/// Writes output_mesh(in) with `points` (of output_mesh(in)) for its
/// coordinates: the array is swapped into the mesh for the write and back,
/// so that a frame's output costs no copy of the cells nor of the points.
/// `in` and `points` are as they were on return, also when the write throws.
void write_output_mesh(JobInputs& in, const std::filesystem::path& path, std::vector<double>& points,
                       const MeshFields& fields, const WriteOptions& options);

/// `points` (of in.mesh) as points of output_mesh(in): themselves, or the 2D
/// case's 3D points (lift_points) in `buffer`.
std::span<const double> output_points(const JobInputs& in, std::span<const double> points,
                                      std::vector<double>& buffer);
/// The same for an array: `points` itself, or `buffer`.
std::vector<double>& output_points(const JobInputs& in, std::vector<double>& points, std::vector<double>& buffer);

}  // namespace dgwarp
