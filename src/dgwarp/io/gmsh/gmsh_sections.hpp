#pragma once
// The sections of a Gmsh ASCII file, parsed into raw content (internal to the
// Gmsh reader; gmsh_read.cpp turns the content into a Mesh).
//
// Each read_* function is called with the reader on the section's header line
// ("$Nodes") and returns with it on the matching end line ("$EndNodes"). Every
// record is one line, as Gmsh writes them. Errors are ParseError naming the
// file, line and what was expected, or FormatError for unsupported variants.
#include <cstddef>
#include <cstdint>
#include <map>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "dgwarp/io/gmsh/gmsh_node_tags.hpp"
#include "dgwarp/io/text_reader.hpp"
#include "dgwarp/mesh/mesh.hpp"

namespace dgwarp::msh {

/// The elements of one dimension, in file order, with their physical groups.
struct ElementsOfDimension {
    ElementList elements;               // VTK node order, 0-based node ids
    std::vector<std::uint32_t> groups;  // per element: index into GmshContent::group_tags
};

/// Everything the reader keeps from a file.
struct GmshContent {
    /// `file_size` (bytes) bounds every reservation made from counts in the file.
    explicit GmshContent(std::size_t file_size);

    std::size_t file_size;
    int version = 0;  // 41 or 22, from $MeshFormat
    std::map<std::pair<int, int>, std::string> physical_names;         // (dim, tag) -> name
    std::map<std::pair<int, int>, std::vector<int>> entity_physicals;  // 4.1: (dim, entity tag) -> tags
    bool has_entities = false, has_nodes = false, has_elements = false;

    std::vector<double> xyz;  // num nodes × 3, row-major, file order
    NodeTagMap node_ids;      // Gmsh node tag -> row of xyz

    int top_dim = -1;                   // highest dimension of any element (points included)
    ElementsOfDimension by_dim[4];      // by_dim[0] stays empty: points are not kept
    std::vector<std::vector<int>> group_tags{{}};  // sorted unique physical tags; [0] = none

    /// Index in group_tags of the set `tags` (sorted and deduplicated here).
    std::uint32_t group_of(std::vector<int> tags);

private:
    std::map<std::vector<int>, std::uint32_t> group_index_{{{}, 0}};
};

/// $MeshFormat: sets content.version (41 or 22). Throws FormatError for a
/// binary file or another version.
void read_mesh_format(TextReader& r, GmshContent& content);

/// $PhysicalNames: `dim tag "name"` lines.
void read_physical_names(TextReader& r, GmshContent& content);

/// $Entities (4.1): the physical tags of every point, curve, surface and volume.
void read_entities(TextReader& r, GmshContent& content);

/// $Nodes (4.1 entity blocks or the 2.2 list, by content.version).
void read_nodes(TextReader& r, GmshContent& content);

/// $Elements (4.1 entity blocks or the 2.2 list, by content.version); needs
/// $Nodes (and, for 4.1 physical groups, $Entities) read before.
void read_elements(TextReader& r, GmshContent& content);

/// Any other section `$<name>`: skipped up to `$End<name>`.
void skip_section(TextReader& r, std::string_view name);

}  // namespace dgwarp::msh
