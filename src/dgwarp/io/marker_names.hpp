#pragma once
// Marker names across formats: renaming markers (`--rename-marker OLD=NEW`),
// and names an output format cannot hold (an OpenFOAM patch is one word; a
// CGNS name at most 32 characters without '/'; an SU2 tag one line) made
// into names it can, said in a warning (`convert`).
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "dgwarp/mesh/mesh.hpp"

namespace dgwarp {

struct MarkerRename {
    std::string from, to;
};

/// "OLD=NEW" (the last '=' splits, so OLD may hold one); an empty string when
/// `text` is one, else why not.
std::string marker_rename_problem(std::string_view text);
MarkerRename parse_marker_rename(std::string_view text);  // text must pass marker_rename_problem

/// Renames each `from` marker of `mesh` to `to`, in order. Throws MeshError
/// naming the marker (and listing the mesh's) when `from` is not one, or when
/// `to` is another marker's name.
void rename_markers(Mesh& mesh, const std::vector<MarkerRename>& renames);

/// Whether `name` can name an OpenFOAM patch: one word (not empty, no blanks,
/// quotes, slashes or any of ( ) { } ;).
bool is_openfoam_word(std::string_view name);

/// Renames the markers whose names the format of `output` (by its extension,
/// or an OpenFOAM case folder) cannot hold: characters it cannot hold become
/// '_', blanks at either end are dropped, a CGNS name is cut to 32 characters,
/// and a name already taken gets "_2", "_3", ...; returns the renames made, in
/// marker order (none for a format that holds every name: Gmsh, VTU).
std::vector<MarkerRename> make_marker_names_writable(Mesh& mesh, const std::filesystem::path& output);

}  // namespace dgwarp
