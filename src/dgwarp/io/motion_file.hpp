#pragma once
// Reading a motion file (JSON; the schema is in docs/MOTION.md) into a
// MotionSpec, and writing one. The files it names (displacement CSV, SU2 surface file, node
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
#include <vector>

#include "dgwarp/motion/motion_spec.hpp"

namespace dgwarp {

/// Reads and checks the motion file at `path`.
MotionSpec read_motion_file(const std::filesystem::path& path);

/// Parses motion-file `text`; `file_name` names it in messages and
/// `base_dir` is where relative file names in it are looked up.
MotionSpec parse_motion_file(const std::string& text, const std::string& file_name,
                             const std::filesystem::path& base_dir);

/// Writes `spec` as the motion file `path` (JSON, docs/MOTION.md; `comment`,
/// when not empty, as its top-level "comment") and each node table it holds
/// as a node file beside it, named <stem>_<marker>[_<frame>].csv (.dat for
/// new positions, an SU2 surface file); tables that share a source (or, built
/// in code, an object) share one file. read_motion_file(path) gives back the
/// same motions bit for bit: numbers are written in their shortest exact
/// form, angles in the degrees the reader turns back into the same radians.
/// The one exception: a rotation about an axis other than x, y or z, whose
/// rotation vector is written as angle_deg and axis to within rounding.
/// Every file is written atomically (atomic_write.hpp), the node files before
/// the motion file that names them. Returns the files written, the motion
/// file last. Throws IoError when a file cannot be written.
std::vector<std::filesystem::path> write_motion_file(const std::filesystem::path& path, const MotionSpec& spec,
                                                     const std::string& comment = "");

/// The node files `spec`'s tables were read from (their `source`), each once,
/// in order of first use: the files reading its motion file read besides it,
/// which no output may be.
std::vector<std::filesystem::path> motion_named_files(const MotionSpec& spec);

}  // namespace dgwarp
