// $Nodes and $Elements of the Gmsh reader (declared in gmsh_sections.hpp).
#include <algorithm>
#include <array>
#include <limits>
#include <map>
#include <optional>
#include <set>
#include <string>

#include "dgwarp/io/gmsh/gmsh_element_types.hpp"
#include "dgwarp/io/gmsh/gmsh_record.hpp"
#include "dgwarp/io/gmsh/gmsh_sections.hpp"
#include "dgwarp/io/record_lines.hpp"

namespace dgwarp::msh {

namespace {

using ElementNodes = std::array<NodeId, 8>;

// Reads a node tag, checks it is new and maps it to the next node id.
void read_node_tag(TextReader& r, GmshContent& c, NodeId id) {
    const std::int64_t tag = r.next_int("a node tag");
    if (tag <= 0) r.fail("a positive node tag", std::to_string(tag));
    if (!c.node_ids.insert(tag, id)) r.fail("a node tag not used before", std::to_string(tag));
}

void read_coordinates(TextReader& r, GmshContent& c) {
    for (const char* axis : {"the x coordinate", "the y coordinate", "the z coordinate"})
        c.xyz.push_back(r.next_double(axis));
}

void check_node_total(TextReader& r, std::int64_t total) {
    if (total > std::numeric_limits<NodeId>::max())
        r.fail("at most " + std::to_string(std::numeric_limits<NodeId>::max()) + " nodes", std::to_string(total));
}

// The fast paths of a block (record_lines.hpp): its lines on several
// threads, accepting only what the line-by-line code accepts; false sends
// the block back to it, which names the error. Gmsh's records skip blank
// lines; a line beginning with '$' is never a record.
constexpr SkippedLines gmsh_skipped{};

/// `n` coordinate lines 'x y z' appended to c.xyz.
bool read_coordinates_fast(TextReader& r, GmshContent& c, std::int64_t n) {
    const std::optional<RecordBlock> block = split_record_lines(r, n, gmsh_skipped);
    if (!block) return false;
    const std::size_t first = c.xyz.size();
    c.xyz.resize(first + 3 * static_cast<std::size_t>(n));
    const bool ok = parse_record_chunks(r, *block, [&](std::size_t k) {
        return for_each_record_line(r.content(), block->chunks[k], gmsh_skipped,
                                    [&](std::string_view line, std::int64_t record, std::size_t) {
                                        LineTokens tokens(line);
                                        double* x = c.xyz.data() + first + 3 * static_cast<std::size_t>(record);
                                        for (int d = 0; d < 3; ++d)
                                            if (!parse_double(tokens.next(), x[d])) return false;
                                        return tokens.next().empty();
                                    });
    });
    if (!ok) {
        c.xyz.resize(first);
        return false;
    }
    r.seek(block->end, block->last_line);
    return true;
}

/// `n` element lines 'tag nodeTags...' of type t (4.1) appended to c.
bool read_elements_fast(TextReader& r, GmshContent& c, CellType t, std::int64_t n, std::uint32_t group) {
    const std::optional<RecordBlock> block = split_record_lines(r, n, gmsh_skipped);
    if (!block) return false;
    const int k = nodes_per_cell(t);
    const auto order = gmsh_index_of_vtk_node(t);
    const int dim = cell_dimension(t);
    // Elements of dimension 0 (points) are read and checked, and kept nowhere.
    ElementList points;
    ElementList& out = dim > 0 ? c.by_dim[dim].elements : points;
    const bool ok = parse_element_chunks(r, *block, out, [&](std::size_t ci, ElementList& part) {
        part.reserve(static_cast<std::size_t>(block->chunks[ci].count), k);
        return for_each_record_line(r.content(), block->chunks[ci], gmsh_skipped,
                                    [&](std::string_view line, std::int64_t, std::size_t) {
                                        LineTokens tokens(line);
                                        std::int64_t tag = 0;
                                        const std::string_view first = tokens.next();
                                        if (!first.empty() && first.front() == '$') return false;
                                        if (!parse_int(first, tag) || tag <= 0) return false;
                                        ElementNodes gmsh_order{}, vtk_order{};
                                        for (int i = 0; i < k; ++i) {
                                            const std::string_view token = tokens.next();
                                            if (!(parse_plain_digits(token, tag) || parse_int(token, tag))) return false;
                                            gmsh_order[i] = c.node_ids.find(tag);
                                            if (gmsh_order[i] < 0) return false;
                                        }
                                        if (!tokens.next().empty()) return false;
                                        for (int i = 0; i < k; ++i) vtk_order[i] = gmsh_order[order[i]];
                                        part.push_back(t, std::span(vtk_order.data(), static_cast<std::size_t>(k)));
                                        return true;
                                    });
    });
    if (!ok) return false;
    c.top_dim = std::max(c.top_dim, dim);
    if (dim > 0) c.by_dim[dim].groups.resize(c.by_dim[dim].groups.size() + static_cast<std::size_t>(n), group);
    r.seek(block->end, block->last_line);
    return true;
}

void read_nodes_41(TextReader& r, GmshContent& c) {
    require_record(r, "the node counts 'numEntityBlocks numNodes minNodeTag maxNodeTag'");
    const std::size_t header_line = r.line_number();
    const std::int64_t num_blocks = read_count(r, "the number of node blocks");
    const std::int64_t total = read_count(r, "the number of nodes");
    read_count(r, "the smallest node tag");
    read_count(r, "the largest node tag");
    expect_end_of_record(r, "the node counts");
    check_node_total(r, total);
    c.xyz.reserve(3 * reserve_hint(total, c.file_size, 8));

    std::int64_t seen = 0;
    for (std::int64_t b = 0; b < num_blocks; ++b) {
        require_record(r, "a node block header 'entityDim entityTag parametric numNodesInBlock'");
        const int dim = read_dimension(r, "the entity dimension");
        read_int32(r, "the entity tag");
        const std::int64_t parametric = r.next_int("the parametric flag");
        if (parametric != 0 && parametric != 1) r.fail("the parametric flag (0 or 1)", std::to_string(parametric));
        const std::int64_t n = read_count(r, "the number of nodes in the block");
        expect_end_of_record(r, "the node block header");
        if (n > total - seen)
            r.fail("at most " + std::to_string(total - seen) + " nodes in this block (the section header says " +
                       std::to_string(total) + " in all)",
                   std::to_string(n));
        const auto first = static_cast<NodeId>(seen);
        for (std::int64_t i = 0; i < n; ++i) {
            require_record(r, "a node tag");
            read_node_tag(r, c, first + static_cast<NodeId>(i));
            expect_end_of_record(r, "the node tag");
        }
        if (!parametric && read_coordinates_fast(r, c, n)) {
            seen += n;
            continue;
        }
        for (std::int64_t i = 0; i < n; ++i) {
            require_record(r, parametric ? "node coordinates 'x y z u...'" : "node coordinates 'x y z'");
            read_coordinates(r, c);
            if (parametric)
                for (int k = 0; k < dim; ++k) r.next_double("a parametric coordinate");
            expect_end_of_record(r, "the node coordinates");
        }
        seen += n;
    }
    if (seen != total)
        fail_at_line(r, header_line,
                         "a number of nodes equal to the sum over the node blocks (" + std::to_string(seen) + ")",
                         std::to_string(total));
    expect_end_marker(r, "$EndNodes");
}

void read_nodes_22(TextReader& r, GmshContent& c) {
    require_record(r, "the number of nodes");
    const std::int64_t total = read_count(r, "the number of nodes");
    expect_end_of_record(r, "the number of nodes");
    check_node_total(r, total);
    c.xyz.reserve(3 * reserve_hint(total, c.file_size, 8));
    for (std::int64_t i = 0; i < total; ++i) {
        require_record(r, "a node 'tag x y z'");
        read_node_tag(r, c, static_cast<NodeId>(i));
        read_coordinates(r, c);
        expect_end_of_record(r, "the node");
    }
    expect_end_marker(r, "$EndNodes");
}

// "the 3 node tags of a triangle", for each cell type (built once).
std::string_view node_tags_text(CellType t) {
    static const auto texts = [] {
        std::array<std::string, std::size(all_cell_types)> s;
        for (CellType u : all_cell_types)
            s[static_cast<int>(u)] = "the " + std::to_string(nodes_per_cell(u)) + " node tags of a " +
                                     std::string(cell_type_name(u));
        return s;
    }();
    return texts[static_cast<int>(t)];
}

CellType read_element_type(TextReader& r) {
    const std::string_view token = r.require_token("the element type");
    std::int64_t id = 0;
    if (!parse_int(token, id)) r.fail("the element type (an integer)", token);
    const auto t = (id >= 0 && id <= 1000) ? cell_type_from_gmsh_id(static_cast<int>(id)) : std::nullopt;
    if (!t) r.fail(supported_gmsh_types_text(), token);
    return *t;
}

// Reads the node tags of an element of type t (Gmsh order) and returns its
// node ids in VTK order.
ElementNodes read_element_nodes(TextReader& r, const GmshContent& c, CellType t) {
    ElementNodes gmsh_order{};
    const int n = nodes_per_cell(t);
    for (int i = 0; i < n; ++i) {
        const std::int64_t tag = r.next_int(node_tags_text(t));
        const NodeId id = c.node_ids.find(tag);
        if (id < 0) r.fail("a node tag defined in $Nodes", std::to_string(tag));
        gmsh_order[i] = id;
    }
    ElementNodes vtk_order{};
    const auto order = gmsh_index_of_vtk_node(t);
    for (int i = 0; i < n; ++i) vtk_order[i] = gmsh_order[order[i]];
    return vtk_order;
}

void add_element(GmshContent& c, CellType t, const ElementNodes& nodes, std::uint32_t group) {
    const int dim = cell_dimension(t);
    c.top_dim = std::max(c.top_dim, dim);
    if (dim == 0) return;  // points never become cells or marker elements
    c.by_dim[dim].elements.push_back(t, std::span(nodes.data(), static_cast<std::size_t>(nodes_per_cell(t))));
    c.by_dim[dim].groups.push_back(group);
}

void read_elements_41(TextReader& r, GmshContent& c) {
    require_record(r, "the element counts 'numEntityBlocks numElements minElementTag maxElementTag'");
    const std::size_t header_line = r.line_number();
    const std::int64_t num_blocks = read_count(r, "the number of element blocks");
    const std::int64_t total = read_count(r, "the number of elements");
    read_count(r, "the smallest element tag");
    read_count(r, "the largest element tag");
    expect_end_of_record(r, "the element counts");

    std::int64_t seen = 0;
    for (std::int64_t b = 0; b < num_blocks; ++b) {
        require_record(r, "an element block header 'entityDim entityTag elementType numElementsInBlock'");
        const int dim = read_dimension(r, "the entity dimension");
        const int entity = read_int32(r, "the entity tag");
        const CellType t = read_element_type(r);
        if (cell_dimension(t) != dim)
            r.fail("an element type of dimension " + std::to_string(dim) + " (the entity's dimension)",
                   std::string(cell_type_name(t)));
        const std::int64_t n = read_count(r, "the number of elements in the block");
        expect_end_of_record(r, "the element block header");
        if (n > total - seen)
            r.fail("at most " + std::to_string(total - seen) + " elements in this block (the section header says " +
                       std::to_string(total) + " in all)",
                   std::to_string(n));
        // Elements take their physical groups from their entity; an entity
        // missing from $Entities (or no $Entities at all) has none.
        const auto physicals = c.entity_physicals.find({dim, entity});
        const std::uint32_t group = physicals == c.entity_physicals.end() ? 0 : c.group_of(physicals->second);
        if (read_elements_fast(r, c, t, n, group)) {
            seen += n;
            continue;
        }
        for (std::int64_t i = 0; i < n; ++i) {
            require_record(r, "an element 'tag nodeTags...'");
            const std::int64_t tag = r.next_int("the element tag");
            if (tag <= 0) r.fail("a positive element tag", std::to_string(tag));
            const ElementNodes nodes = read_element_nodes(r, c, t);
            expect_end_of_record(r, node_tags_text(t));
            add_element(c, t, nodes, group);
        }
        seen += n;
    }
    if (seen != total)
        fail_at_line(r, header_line,
                         "a number of elements equal to the sum over the element blocks (" + std::to_string(seen) + ")",
                         std::to_string(total));
    expect_end_marker(r, "$EndElements");
}

void read_elements_22(TextReader& r, GmshContent& c) {
    require_record(r, "the number of elements");
    const std::int64_t total = read_count(r, "the number of elements");
    expect_end_of_record(r, "the number of elements");

    // Gmsh 2.2 writes an element that is in several physical groups once per
    // group, on consecutive lines with the same elementary tag; such a run is
    // merged back into one element in all those groups. The run's groups are
    // collected in a set and turned into a group list once, when it ends, so
    // even a long run costs O(k log k).
    struct Run {
        bool open = false;
        CellType type{};
        int elementary = 0;
        ElementNodes nodes{};
        std::set<int> physicals;
        bool merged = false;
    } run;
    const auto close_run = [&] {
        if (run.merged && cell_dimension(run.type) > 0)
            c.by_dim[cell_dimension(run.type)].groups.back() =
                c.group_of(std::vector<int>(run.physicals.begin(), run.physicals.end()));
    };
    std::map<int, std::uint32_t> group_of_physical;  // cache: most elements are in one group

    for (std::int64_t i = 0; i < total; ++i) {
        require_record(r, "an element 'tag type numTags tags... nodeTags...'");
        const std::int64_t tag = r.next_int("the element tag");
        if (tag <= 0) r.fail("a positive element tag", std::to_string(tag));
        const CellType t = read_element_type(r);
        const std::int64_t num_tags = read_count(r, "the number of tags");
        int physical = 0, elementary = 0;
        for (std::int64_t k = 0; k < num_tags; ++k) {
            const int v = read_int32(r, k == 0 ? "the physical tag" : k == 1 ? "the elementary tag" : "a tag");
            if (k == 0) physical = v;
            if (k == 1) elementary = v;
        }
        const ElementNodes nodes = read_element_nodes(r, c, t);
        expect_end_of_record(r, node_tags_text(t));

        if (run.open && physical != 0 && !run.physicals.empty() && t == run.type &&
            elementary == run.elementary && nodes == run.nodes && !run.physicals.contains(physical)) {
            run.physicals.insert(physical);
            run.merged = true;
            continue;
        }
        close_run();
        run = {true, t, elementary, nodes, {}, false};
        std::uint32_t group = 0;
        if (physical != 0) {
            run.physicals.insert(physical);
            const auto [it, inserted] = group_of_physical.emplace(physical, 0);
            if (inserted) it->second = c.group_of({physical});
            group = it->second;
        }
        add_element(c, t, nodes, group);
    }
    close_run();
    expect_end_marker(r, "$EndElements");
}

}  // namespace

void read_nodes(TextReader& r, GmshContent& content) {
    if (content.version == 41)
        read_nodes_41(r, content);
    else
        read_nodes_22(r, content);
    content.has_nodes = true;
}

void read_elements(TextReader& r, GmshContent& content) {
    if (content.version == 41)
        read_elements_41(r, content);
    else
        read_elements_22(r, content);
    content.has_elements = true;
}

}  // namespace dgwarp::msh
