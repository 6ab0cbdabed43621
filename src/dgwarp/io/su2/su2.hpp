#pragma once
// SU2 native ASCII mesh format (https://su2code.github.io/docs_v7/Mesh-File/).
//
// The reader takes the forms real files have: `NDIME=2` or `NDIME= 2`, blanks
// or tabs between numbers, `%` comment lines, CRLF line ends, element and point
// lines with trailing index columns (ignored), `NPOIN= n n_domain`, and FFD,
// periodic or other unknown keyword sections (skipped). Element node order is
// VTK's, as in the neutral Mesh; node ids are 0-based in both.
#include <cstdint>
#include <filesystem>
#include <ostream>
#include <string>
#include <vector>

#include "dgwarp/core/progress.hpp"
#include "dgwarp/mesh/mesh.hpp"

namespace dgwarp {

/// Reads an SU2 ASCII mesh: dim, points (num_points × dim, row-major),
/// volume cells in file order and the markers in file order.
/// `zone` selects the zone (`IZONE=`, 1-based) of a multi-zone file (`NZONE=`);
/// a single-zone file has only zone 1.
/// Throws IoError when the file cannot be read; ParseError (file, line, what
/// was expected, what was found) on malformed content: truncated or miscounted
/// blocks, bad numbers (non-numeric, NaN, inf), unknown element types,
/// elements of the wrong dimension, node ids out of range, missing sections,
/// counts the file cannot hold (rejected before any allocation), an absent
/// zone; MeshError when the result fails validate().
/// `progress` (core/progress.hpp) gets the fraction of the file parsed.
Mesh read_su2(const std::filesystem::path& path, int zone = 1, const ProgressFn& progress = {});

/// An SU2 file's text around the four sections of the zone that was read:
/// what comes before them (comments, NZONE=, earlier zones) and after them
/// (FFD boxes, periodic data, later zones), byte for byte, so that a deformed
/// copy of the file keeps them (write_su2 below).
struct Su2Surroundings {
    std::string before, after;
    bool zone_has_ndime = true;    // false when the zone's dimension is given by an NDIME= before NZONE=
    std::int64_t num_points = 0;   // the zone's: the surroundings may name its nodes (FFD_SURFACE_POINTS)
    std::int64_t num_cells = 0;
    std::int64_t zones = 1;        // zones in the file (NZONE=; 1 for a single-zone file)
    /// What before and after hold, for messages: e.g. "zone 2 of 2", "FFD_NBOX= 1", "NPERIODIC= 1";
    /// empty when they hold nothing but blank lines and comments.
    std::vector<std::string> contents;
};

/// read_su2, also returning the zone's surroundings in `surroundings`.
Mesh read_su2(const std::filesystem::path& path, int zone, const ProgressFn& progress, Su2Surroundings& surroundings);

/// The same, from text in memory; `file_name` is used in error messages.
Mesh read_su2_text(const std::string& file_name, std::string content, int zone = 1);

/// Writes `mesh` as SU2 ASCII to `out`: NDIME, NELEM (one element per line:
/// type id, node ids, element index), NPOIN (coordinates in shortest exact
/// form, point index), NMARK and a MARKER_TAG / MARKER_ELEMS block per marker.
/// Reading it back gives a Mesh equal (operator==) to `mesh`. Throws MeshError,
/// before writing anything, when `mesh` fails validate() or a marker name
/// cannot be stored (empty, duplicated, several lines, surrounding blanks).
void write_su2(std::ostream& out, const Mesh& mesh);

/// Throws the MeshError write_su2 would throw about `mesh` (validate(), a
/// marker name SU2 cannot store), without writing: to check an output before
/// the work.
void check_su2_writable(const Mesh& mesh);

/// Writes `mesh` as SU2 ASCII to `path` through write_file_atomically: on any
/// error `path` is left as it was. Throws IoError (e.g. missing folder) or
/// MeshError as above.
void write_su2(const std::filesystem::path& path, const Mesh& mesh);

/// Writes `mesh` (e.g. the zone deformed) in place of the zone's sections
/// within `surroundings`, atomically: every other zone, FFD box, periodic
/// section and comment of the original file passes through unchanged. Throws
/// MeshError, before writing anything, when `mesh` has not the zone's number
/// of points and cells (the surroundings may refer to its node ids), or as
/// write_su2 above.
void write_su2(const std::filesystem::path& path, const Mesh& mesh, const Su2Surroundings& surroundings);

}  // namespace dgwarp
