#pragma once
// Readers of the per-node files a motion file can name (docs/MOTION.md):
//   displacement CSV   node,dx,dy[,dz]                     (optional header line)
//   node motion CSV    node,tx,ty,tz,wx,wy,wz,cx,cy,cz     (3D; optional header line)
//                      node,tx,ty,wz,cx,cy                 (2D form)
//   SU2 surface file   global_id x y [z]                   (new coordinates; SU2's
//                      DV_KIND= SURFACE_FILE / DV_FILENAME, whitespace separated)
// Node ids are 0-based mesh node ids (for SU2 files, the point's position in
// the .su2 file, which is SU2's global index). Fields are separated by commas
// or by blanks; blank lines and lines starting with '#' or '%' are skipped.
// Every line must have as many fields as the first data line. A node listed
// twice with the same values is kept once (SU2 writes nodes shared by two
// markers twice); with different values it is an error.
// Errors: IoError when the file cannot be read; ParseError with the file and
// the 1-based line for a malformed line, a non-finite number, a negative node
// id or a duplicate node with different values.
#include <filesystem>

#include "dgwarp/motion/motion_spec.hpp"

namespace dgwarp {

/// Reads a displacement CSV: one displacement per node; components = 2 or 3
/// (the number of value columns).
NodeTable<Vec3> read_displacement_csv(const std::filesystem::path& path);

/// Reads a per-node motion CSV (10 fields, or 6 in the 2D form, where
/// tz = wx = wy = cz = 0); components = 3 or 2 accordingly.
NodeTable<NodeMotion> read_node_motion_csv(const std::filesystem::path& path);

/// Reads an SU2 surface file of new positions; components = 2 or 3.
NodeTable<Vec3> read_su2_surface_file(const std::filesystem::path& path);

}  // namespace dgwarp
