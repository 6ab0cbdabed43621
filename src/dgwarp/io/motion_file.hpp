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

#include "dgwarp/motion/motion_spec.hpp"

namespace dgwarp {

/// Reads and checks the motion file at `path`.
MotionSpec read_motion_file(const std::filesystem::path& path);

/// Parses motion-file `text`; `file_name` names it in messages and
/// `base_dir` is where relative file names in it are looked up.
MotionSpec parse_motion_file(const std::string& text, const std::string& file_name,
                             const std::filesystem::path& base_dir);

}  // namespace dgwarp
