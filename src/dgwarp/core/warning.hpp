#pragma once
// Warnings the library gives (it never prints): each a code a program can
// test, the data it is about, and the text a person reads. Callers print
// `text`, or report `code` and the fields (the JSON reports' warning items,
// docs/JSON.md); nobody parses the text.
#include <cstdint>
#include <limits>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace dgwarp {

enum class WarningCode {
    shared_moving_static,        // boundary nodes on a moving and a static marker (count)
    nothing_moves,               // the motion moves no marker
    coincident_boundary_nodes,   // boundary nodes at the same coordinates (count; node: one of them)
    empty_named_marker,          // the motion names a marker without elements (marker)
    large_rotation,              // a marker turns by more than 180 degrees in one step (marker; value: degrees)
    large_displacement,          // a marker moves a node farther than the mesh's diagonal (marker, node; value: distance)
    boundary_folds_faces,        // the boundary motion itself turns faces over (marker, count; element: one of them)
    conflicting_shared_motions,  // a step gave coincident boundary nodes different motions (count: groups)
    outside_hull,                // volume nodes outside the Delaunay graph's hull (count)
    already_inverted,            // cells inverted or degenerate in the input (count; element: the worst)
    cyclic_mismatch,             // other markers move a cyclic node and its image differently (count: groups; node: one)
    stale_frames,                // frame files of an earlier, longer series left beside a job's output (count: files)
    processors_unchanged,        // a decomposed case's processor folders the job does not write (count: folders)
    other,                       // a warning of a program built on the library, with text only
};

/// "shared-moving-static", "nothing-moves", ...: the code as reports print it.
std::string_view warning_code_name(WarningCode code);

struct Warning {
    Warning() = default;
    Warning(WarningCode code, std::string text, std::string marker = {}, std::int64_t count = -1)
        : code(code), text(std::move(text)), marker(std::move(marker)), count(count) {}

    WarningCode code = WarningCode::other;
    std::string text;            // for a person: the whole warning
    std::string marker;          // the marker it is about, or ""
    std::int64_t count = -1;     // how many nodes, cells, faces or groups, or -1
    std::int64_t node = -1;      // a node it is about (an example), or -1
    std::int64_t element = -1;   // a cell or marker element it is about (an example), or -1
    double value = std::numeric_limits<double>::quiet_NaN();  // a figure it is about (an angle, a distance), or NaN
};

/// The texts of `warnings`, in order.
std::vector<std::string> warning_texts(const std::vector<Warning>& warnings);

}  // namespace dgwarp
