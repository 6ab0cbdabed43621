#pragma once
// Reading a motion file (JSON; the schema is in docs/MOTION.md) into a
// MotionSpec. The files it names (displacement CSV, SU2 surface file, node
// motion CSV) are read too; relative paths are relative to the motion file's
// folder.
//
// Errors: IoError when a file cannot be read (for a named file, the message
// says which field named it); ParseError naming the file and, for JSON, the
// path of the bad value (`markers.airfoil.rotate.angle_deg`) or the line of a
// syntax error, and for CSV files the line. Nothing here needs a mesh: marker
// names and node ids are checked against the mesh by resolve_motion.
#include <filesystem>
#include <string>

#include "dgwarp/mesh/mesh.hpp"
#include "dgwarp/motion/motion_spec.hpp"

namespace dgwarp {

/// Reads and checks the motion file at `path`.
MotionSpec read_motion_file(const std::filesystem::path& path);

/// Parses motion-file `text`; `file_name` names it in messages and
/// `base_dir` is where relative file names in it are looked up.
MotionSpec parse_motion_file(const std::string& text, const std::string& file_name,
                             const std::filesystem::path& base_dir);

/// Writes `spec` (for `mesh`: its dimension, and the nodes of a marker whose
/// rigid motion needs a node file) as the motion file `path`, atomically,
/// with each per-node table as a CSV file beside it (the motion file's stem,
/// "_", the marker's name, ".csv"; with the frame's number in a list of
/// frames). read_motion_file then gives the same per-node motions bit for
/// bit: rotations about a coordinate axis as angle_deg (the exact double),
/// other rigid motions as node_motion_file tables, numbers in shortest exact
/// form. Throws Error for what it cannot write (periodic motions, new
/// positions per node), MeshError for a marker the mesh lacks, IoError.
void write_motion_file(const std::filesystem::path& path, const MotionSpec& spec, const Mesh& mesh);

}  // namespace dgwarp
