// Gmsh reader: the section loop and the assembly of the Mesh.
#include <filesystem>
#include <map>
#include <set>
#include <sstream>

#include "dgwarp/core/error.hpp"
#include "dgwarp/io/gmsh/gmsh.hpp"
#include "dgwarp/io/gmsh/gmsh_sections.hpp"
#include "dgwarp/io/number_text.hpp"
#include "dgwarp/io/text_reader.hpp"

namespace dgwarp {

namespace {

void read_sections(TextReader& r, msh::GmshContent& c) {
    if (!r.next_nonblank_line()) r.fail("$MeshFormat (a Gmsh .msh file)", "end of file");
    if (trim(r.line()) != "$MeshFormat") r.fail("$MeshFormat on the first line (a Gmsh .msh file)", trim(r.line()));
    msh::read_mesh_format(r, c);

    while (r.next_nonblank_line()) {
        const std::string_view header = trim(r.line());
        if (header.size() < 2 || header.front() != '$' || header.starts_with("$End"))
            r.fail("a section header such as $Nodes or $Elements", header);
        const std::string_view name = header.substr(1);
        if (name == "PhysicalNames") {
            msh::read_physical_names(r, c);
        } else if (name == "Entities" && c.version == 41) {
            if (c.has_entities) r.fail("a single $Entities section", header);
            if (c.has_nodes || c.has_elements) r.fail("$Entities before $Nodes and $Elements", header);
            msh::read_entities(r, c);
        } else if (name == "Nodes") {
            if (c.has_nodes) r.fail("a single $Nodes section", header);
            msh::read_nodes(r, c);
        } else if (name == "Elements") {
            if (c.has_elements) r.fail("a single $Elements section", header);
            if (!c.has_nodes) r.fail("$Nodes before $Elements", header);
            msh::read_elements(r, c);
        } else if (name == "PartitionedEntities") {
            // Elements of a partitioned mesh take their physical groups from
            // this section; ignoring it would silently drop every marker.
            throw FormatError(r.file() + ": partitioned MSH files are not supported; save the mesh "
                              "before partitioning it");
        } else {
            msh::skip_section(r, name);  // $Periodic, $NodeData, $Comments, ...
        }
    }
    if (!c.has_nodes) r.fail("a $Nodes section", "end of file");
    if (!c.has_elements) r.fail("an $Elements section", "end of file");
}

// The sorted physical tags of dimension `dim`: named ones, ones given to
// entities and ones carried by elements of that dimension.
std::set<int> physical_tags_of_dimension(const msh::GmshContent& c, int dim) {
    std::set<int> tags;
    for (const auto& [key, name] : c.physical_names)
        if (key.first == dim) tags.insert(key.second);
    for (const auto& [key, physicals] : c.entity_physicals)
        if (key.first == dim) tags.insert(physicals.begin(), physicals.end());
    std::vector<bool> used(c.group_tags.size(), false);
    for (std::uint32_t g : c.by_dim[dim].groups) used[g] = true;
    for (std::size_t g = 0; g < used.size(); ++g)
        if (used[g]) tags.insert(c.group_tags[g].begin(), c.group_tags[g].end());
    return tags;
}

Mesh assemble_mesh(const std::string& file, msh::GmshContent& c) {
    if (c.top_dim < 2)
        throw MeshError(file + ": the mesh has no 2D or 3D elements (highest element dimension: " +
                        std::to_string(c.top_dim) + "); dgwarp needs a surface or volume mesh");
    Mesh mesh;
    mesh.dim = c.top_dim;
    const std::size_t n = c.xyz.size() / 3;
    if (mesh.dim == 2) {
        // A 2D mesh must lie in the z = 0 plane: dgwarp's 2D points have no z.
        for (std::size_t i = 0; i < n; ++i)
            if (c.xyz[3 * i + 2] != 0)
                throw MeshError(file + ": the highest-dimension elements are 2D, so this is a 2D mesh, but node " +
                                    std::to_string(i) + " has z = " + number_text(c.xyz[3 * i + 2]) +
                                    "; dgwarp reads 2D meshes only in the z = 0 plane (surface meshes in 3D "
                                    "are not supported)",
                                "", static_cast<std::int64_t>(i));
        mesh.points.resize(2 * n);
        for (std::size_t i = 0; i < n; ++i) {
            mesh.points[2 * i] = c.xyz[3 * i];
            mesh.points[2 * i + 1] = c.xyz[3 * i + 1];
        }
    } else {
        mesh.points = std::move(c.xyz);
    }
    mesh.cells = std::move(c.by_dim[mesh.dim].elements);

    // One marker per physical group of dimension dim - 1, in tag order.
    const int bdim = mesh.dim - 1;
    std::map<int, std::size_t> marker_of_tag;
    std::map<std::string, int> tag_of_name;
    for (int tag : physical_tags_of_dimension(c, bdim)) {
        const auto name = c.physical_names.find({bdim, tag});
        std::string marker = name != c.physical_names.end() ? name->second : "physical_" + std::to_string(tag);
        // As the SU2 reader: a motion names markers, so two groups of one
        // name would both move (the far field with the airfoil).
        if (const auto [other, added] = tag_of_name.emplace(marker, tag); !added)
            throw MeshError(file + ": the physical groups " + std::to_string(other->second) + " and " +
                                std::to_string(tag) + " of dimension " + std::to_string(bdim) + " are both named '" +
                                marker + "'; marker names must be unique (rename one in $PhysicalNames)",
                            marker);
        marker_of_tag[tag] = mesh.markers.size();
        mesh.markers.push_back({std::move(marker), {}});
    }
    const msh::ElementsOfDimension& boundary = c.by_dim[bdim];
    for (std::size_t i = 0; i < boundary.elements.size(); ++i)
        for (int tag : c.group_tags[boundary.groups[i]])
            mesh.markers[marker_of_tag.at(tag)].elements.push_back(boundary.elements.types[i],
                                                                   boundary.elements.nodes_of(i));
    validate(mesh);
    return mesh;
}

Mesh read_gmsh_from(TextReader& r, std::size_t file_size) {
    msh::GmshContent content(file_size);
    read_sections(r, content);
    return assemble_mesh(r.file(), content);
}

}  // namespace

Mesh read_gmsh(const std::filesystem::path& path, const ProgressFn& progress) {
    TextReader r = TextReader::open(path);
    r.set_progress(progress);
    std::error_code ec;
    const auto size = std::filesystem::file_size(path, ec);
    Mesh mesh = read_gmsh_from(r, ec ? 0 : static_cast<std::size_t>(size));
    if (progress) progress(1.0);
    return mesh;
}

Mesh read_gmsh_text(const std::string& file_name, std::string content) {
    const std::size_t size = content.size();
    TextReader r(file_name, std::move(content));
    return read_gmsh_from(r, size);
}

}  // namespace dgwarp
