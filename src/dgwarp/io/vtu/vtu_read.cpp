// Reader of VTK XML unstructured grids (.vtu): the file's structure and the
// assembly of the Mesh. The XML is scanned by vtk_xml, each DataArray decoded
// by vtu_data_array.
#include <cmath>
#include <fstream>
#include <limits>
#include <map>
#include <optional>

#include "dgwarp/core/error.hpp"
#include "dgwarp/io/number_text.hpp"
#include "dgwarp/io/text_reader.hpp"
#include "dgwarp/io/vtu/vtk_xml.hpp"
#include "dgwarp/io/vtu/vtu.hpp"
#include "dgwarp/io/vtu/vtu_data_array.hpp"
#include "dgwarp/mesh/polyhedron_faces.hpp"

namespace dgwarp {

namespace {

// Node ids must fit NodeId, and so must their count.
constexpr std::int64_t max_node_count = std::numeric_limits<NodeId>::max();

std::string str(std::int64_t v) { return std::to_string(v); }

/// A VTK cell type dgwarp reads: its CellType and, for VTK's pixel and voxel
/// (axis-aligned quad and hexahedron numbered in lexicographic order), the
/// permutation to the usual node order.
struct VtkCell {
    CellType type;
    const int* order = nullptr;  // nodes_per_cell(type) entries; null: as in the file
};

constexpr int pixel_order[] = {0, 1, 3, 2};
constexpr int voxel_order[] = {0, 1, 3, 2, 4, 5, 7, 6};

std::optional<VtkCell> vtk_cell(std::int64_t id) {
    if (id == 8) return VtkCell{CellType::quadrilateral, pixel_order};
    if (id == 11) return VtkCell{CellType::hexahedron, voxel_order};
    if (id < 0 || id > 255) return std::nullopt;
    if (const std::optional<CellType> t = cell_type_from_vtk_id(static_cast<int>(id))) return VtkCell{*t};
    return std::nullopt;
}

constexpr const char* supported_cells =
    "a linear VTK cell type (1 vertex, 3 line, 5 triangle, 7 polygon, 8 pixel, 9 quad, 10 tetra, 11 voxel, "
    "12 hexahedron, 13 wedge, 14 pyramid, 42 polyhedron)";

// The arrays of dgwarp's markers, in the grid's <FieldData> (see vtu.hpp).
constexpr const char* marker_arrays[] = {"dgwarp_marker_names", "dgwarp_marker_sizes", "dgwarp_marker_types",
                                         "dgwarp_marker_connectivity"};

/// Every cell of every piece, with node ids into the pieces' joined points.
struct Cells {
    ElementList elements;
    std::vector<std::int64_t> physical;  // meshio's gmsh:physical per cell; empty when a piece lacks it
    bool physical_complete = true;
};

class VtuReader {
public:
    VtuReader(const std::string& file, std::string_view content, ProgressFn progress)
        : file_(file), content_(content), progress_(std::move(progress)) {}

    Mesh read() {
        report(0.0);
        doc_ = xml::scan(file_, content_);
        const xml::Element& root = doc_.elements[0];
        read_header(root);
        const auto grids = children(root, "UnstructuredGrid");
        if (grids.size() != 1)
            fail(root, "one <UnstructuredGrid> in <VTKFile>", str(static_cast<std::int64_t>(grids.size())));
        const xml::Element& grid = *grids[0];
        const auto pieces = children(grid, "Piece");
        if (pieces.empty()) fail(grid, "a <Piece> in <UnstructuredGrid>", "none");

        std::vector<double> xyz;
        Cells cells;
        for (const xml::Element* piece : pieces) read_piece(*piece, xyz, cells);
        return assemble(grid, std::move(xyz), std::move(cells));
    }

private:
    [[noreturn]] void fail(const xml::Element& e, const std::string& expected, const std::string& found) const {
        throw ParseError(file_, xml::line_at(content_, e.offset), expected, found);
    }

    std::vector<const xml::Element*> children(const xml::Element& e, std::string_view name) const {
        std::vector<const xml::Element*> found;
        for (std::size_t c : e.children)
            if (doc_.elements[c].name == name) found.push_back(&doc_.elements[c]);
        return found;
    }

    /// The only child called `name`, or null when there is none.
    const xml::Element* optional_child(const xml::Element& e, std::string_view name) const {
        const auto found = children(e, name);
        if (found.size() > 1)
            fail(*found[1], "a single <" + std::string(name) + "> in <" + e.name + ">", "a second one");
        return found.empty() ? nullptr : found[0];
    }

    /// The DataArray (or Array) called `name` among `e`'s children, or null.
    const xml::Element* array_named(const xml::Element& e, std::string_view name) const {
        for (std::size_t c : e.children) {
            const xml::Element& a = doc_.elements[c];
            const std::string* n = a.attribute("Name");
            if ((a.name == "DataArray" || a.name == "Array") && n && *n == name) return &a;
        }
        return nullptr;
    }

    void report(double fraction) {
        if (!progress_ || fraction < reported_) return;
        reported_ = fraction;
        progress_(fraction);
    }

    /// Reports how far into the file the data of `array` ends.
    void report_after(const xml::Element& array) {
        std::size_t at = array.offset;
        if (!array.text.empty()) at = array.text.back().second;
        if (const std::string* offset = array.attribute("offset"); offset && enc_.appended != std::string_view::npos) {
            std::int64_t o = 0;
            if (parse_int(trim(*offset), o) && o >= 0) at = enc_.appended + static_cast<std::size_t>(o);
        }
        if (!content_.empty()) report(std::min(1.0, static_cast<double>(at) / static_cast<double>(content_.size())));
    }

    void read_header(const xml::Element& root) {
        if (root.name != "VTKFile") fail(root, "<VTKFile> as the root element (a VTK XML file)", "<" + root.name + ">");
        const std::string* type = root.attribute("type");
        if (!type) fail(root, "a type attribute in <VTKFile> (type=\"UnstructuredGrid\")", "none");
        if (*type != "UnstructuredGrid")
            throw FormatError(file_ + ":" + str(static_cast<std::int64_t>(xml::line_at(content_, root.offset))) +
                              ": a VTK XML file of type " + *type +
                              "; dgwarp reads unstructured grids (type=\"UnstructuredGrid\", .vtu)");
        enc_.file = &file_;
        enc_.content = content_;
        if (const std::string* order = root.attribute("byte_order")) {
            if (*order != "LittleEndian" && *order != "BigEndian")
                fail(root, "byte_order=\"LittleEndian\" or \"BigEndian\"", *order);
            enc_.big_endian = *order == "BigEndian";
        }
        if (const std::string* header = root.attribute("header_type")) {
            if (*header != "UInt32" && *header != "UInt64") fail(root, "header_type=\"UInt32\" or \"UInt64\"", *header);
            enc_.header_bytes = *header == "UInt64" ? 8 : 4;
        }
        if (const std::string* compressor = root.attribute("compressor"); compressor && !compressor->empty()) {
            if (*compressor != "vtkZLibDataCompressor")
                throw FormatError(file_ + ":" + str(static_cast<std::int64_t>(xml::line_at(content_, root.offset))) +
                                  ": data compressed by " + *compressor +
                                  ", which dgwarp cannot read; it reads uncompressed data and vtkZLibDataCompressor "
                                  "(in ParaView: Save Data, Compressor Type None or ZLib)");
            enc_.zlib = true;
        }
        enc_.appended = doc_.appended_data;
        if (enc_.appended != std::string_view::npos) {
            const xml::Element& appended = doc_.elements[doc_.appended_element];
            const std::string* encoding = appended.attribute("encoding");
            if (!encoding || (*encoding != "raw" && *encoding != "base64"))
                fail(appended, "encoding=\"raw\" or \"base64\" in <AppendedData>", encoding ? *encoding : "none");
            enc_.appended_raw = *encoding == "raw";
        }
    }

    std::int64_t count_attribute(const xml::Element& e, const char* name, std::int64_t most) const {
        const std::string* text = e.attribute(name);
        std::int64_t n = -1;
        if (!text || !parse_int(trim(*text), n) || n < 0)
            fail(e, std::string("a count >= 0 in attribute ") + name + " of <" + e.name + ">", text ? *text : "none");
        if (n > most) fail(e, std::string(name) + " at most " + str(most), *text);
        return n;
    }

    vtu::ArrayRef data_array(const xml::Element& section, std::string_view name, const std::string& piece) const {
        const xml::Element* a = nullptr;
        if (name.empty()) {
            for (std::size_t c : section.children)
                if (doc_.elements[c].name == "DataArray") {
                    a = &doc_.elements[c];
                    break;
                }
        } else {
            a = array_named(section, name);
        }
        if (!a)
            fail(section, "a DataArray" + (name.empty() ? std::string() : " Name=\"" + std::string(name) + "\"") +
                              " in <" + section.name + ">" + piece,
                 "none");
        return {a, "DataArray '" + (name.empty() ? std::string("Points") : std::string(name)) + "' of <" +
                       section.name + ">" + piece};
    }

    void read_piece(const xml::Element& piece, std::vector<double>& xyz, Cells& cells) {
        const std::size_t first_point = xyz.size() / 3;
        const std::string where = piece_count_ > 0 ? " (piece " + str(piece_count_ + 1) + ")" : "";
        ++piece_count_;
        const std::int64_t num_points =
            count_attribute(piece, "NumberOfPoints", max_node_count - static_cast<std::int64_t>(first_point));
        const std::int64_t num_cells = count_attribute(piece, "NumberOfCells", std::numeric_limits<std::int64_t>::max());
        const std::string points_line = " on line " + str(static_cast<std::int64_t>(xml::line_at(content_, piece.offset)));

        // Points: 3 components, finite.
        if (const xml::Element* points = optional_child(piece, "Points")) {
            const vtu::ArrayRef a = data_array(*points, "", where);
            const std::string* components = a.element->attribute("NumberOfComponents");
            if (!components || trim(*components) != "3")
                vtu::fail_at(enc_, a, "NumberOfComponents=\"3\"", components ? *components : "none (1)");
            const std::vector<double> v = vtu::read_doubles(
                enc_, a, static_cast<std::size_t>(num_points) * 3, "3 per point × NumberOfPoints " + str(num_points) + points_line);
            for (std::size_t i = 0; i < v.size(); ++i)
                if (!std::isfinite(v[i]))
                    vtu::fail_at(enc_, a, "finite coordinates",
                                 number_text(v[i]) + " (point " + str(static_cast<std::int64_t>(i / 3)) + ", coordinate " +
                                     str(static_cast<std::int64_t>(i % 3 + 1)) + ")");
            xyz.insert(xyz.end(), v.begin(), v.end());
            report_after(*a.element);
        } else if (num_points > 0) {
            fail(piece, "<Points> in a <Piece> of NumberOfPoints " + str(num_points), "none");
        }

        const xml::Element* cell_section = optional_child(piece, "Cells");
        if (!cell_section) {
            if (num_cells > 0) fail(piece, "<Cells> in a <Piece> of NumberOfCells " + str(num_cells), "none");
            return;
        }
        const std::string cells_reason = "NumberOfCells " + str(num_cells) + points_line;
        const vtu::ArrayRef types_ref = data_array(*cell_section, "types", where);
        const vtu::ArrayRef offsets_ref = data_array(*cell_section, "offsets", where);
        const vtu::ArrayRef conn_ref = data_array(*cell_section, "connectivity", where);
        const auto n = static_cast<std::size_t>(num_cells);
        const std::vector<std::int64_t> types = vtu::read_integers(enc_, types_ref, n, cells_reason);
        const std::vector<std::int64_t> offsets = vtu::read_integers(enc_, offsets_ref, n, cells_reason);
        // Each cell's node count from its type, checked against the offsets.
        std::vector<VtkCell> kinds(n);
        std::int64_t end = 0;
        for (std::size_t i = 0; i < n; ++i) {
            const std::optional<VtkCell> k = vtk_cell(types[i]);
            if (!k) vtu::fail_at(enc_, types_ref, supported_cells, "type " + str(types[i]) + " (cell " + str(static_cast<std::int64_t>(i)) + ")");
            kinds[i] = *k;
            const int nodes = nodes_per_cell(k->type);
            const int least = k->type == CellType::polygon ? 3 : 4;  // polygons and polyhedra
            if (offsets[i] < end || (nodes > 0 && offsets[i] - end != nodes) || (nodes == 0 && offsets[i] - end < least))
                vtu::fail_at(enc_, offsets_ref,
                             "offsets that give cell " + str(static_cast<std::int64_t>(i)) + " (VTK type " + str(types[i]) + ", " +
                                 std::string(cell_type_name(k->type)) + ") its " +
                                 (nodes > 0 ? str(nodes) : "at least " + str(least)) + " nodes",
                             "offset " + str(offsets[i]) + " after " + str(end));
            end = offsets[i];
        }
        const std::vector<std::int64_t> conn = vtu::read_integers(
            enc_, conn_ref, static_cast<std::size_t>(end), "the last offset, " + str(end));
        for (std::size_t k = 0; k < conn.size(); ++k)
            if (conn[k] < 0 || conn[k] >= num_points)
                vtu::fail_at(enc_, conn_ref,
                             "node ids from 0 to " + str(num_points - 1) + " (NumberOfPoints " + str(num_points) + points_line + ")",
                             str(conn[k]) + " (connectivity value " + str(static_cast<std::int64_t>(k)) + ")");
        report_after(*conn_ref.element);

        const PolyhedronFaces faces = read_polyhedron_faces(*cell_section, kinds, num_points, where);
        cells.elements.reserve(cells.elements.size() + n, 4);
        std::vector<NodeId> nodes;
        for (std::size_t i = 0; i < n; ++i) {
            const std::int64_t first = i == 0 ? 0 : offsets[i - 1];
            const auto count = static_cast<std::size_t>(offsets[i] - first);
            const std::int64_t* c = conn.data() + first;
            if (kinds[i].type == CellType::polyhedron) {
                polyhedron_of(faces, i, {c, count}, static_cast<NodeId>(first_point), xyz, cells.elements);
                continue;
            }
            nodes.resize(count);
            for (std::size_t k = 0; k < count; ++k)
                nodes[k] = static_cast<NodeId>(first_point) + static_cast<NodeId>(c[kinds[i].order ? kinds[i].order[k] : k]);
            cells.elements.push_back(kinds[i].type, nodes);
        }

        // meshio's boundary tags, read only while every piece has them.
        const xml::Element* cell_data = optional_child(piece, "CellData");
        const xml::Element* physical = cell_data ? array_named(*cell_data, "gmsh:physical") : nullptr;
        if (physical && vtu::is_integer_array(*physical) && cells.physical_complete) {
            const std::vector<std::int64_t> tags = vtu::read_integers(
                enc_, {physical, "DataArray 'gmsh:physical' of <CellData>" + where}, n, cells_reason);
            cells.physical.insert(cells.physical.end(), tags.begin(), tags.end());
        } else if (n > 0) {
            cells.physical_complete = false;
        }
    }

    /// A piece's polyhedra (VTK's "faces" and "faceoffsets" arrays of
    /// <Cells>): per cell the start and end of its face stream (-1 for cells
    /// that are not polyhedra), every value checked.
    struct PolyhedronFaces {
        std::vector<std::int64_t> stream, first, end;
        vtu::ArrayRef ref{};
    };
    PolyhedronFaces read_polyhedron_faces(const xml::Element& cell_section, const std::vector<VtkCell>& kinds,
                                          std::int64_t num_points, const std::string& where) const {
        PolyhedronFaces f;
        const std::size_t n = kinds.size();
        if (std::none_of(kinds.begin(), kinds.end(), [](const VtkCell& k) { return k.type == CellType::polyhedron; }))
            return f;
        const vtu::ArrayRef offsets_ref = data_array(cell_section, "faceoffsets", where);
        f.ref = data_array(cell_section, "faces", where);
        const std::vector<std::int64_t> ends = vtu::read_integers(enc_, offsets_ref, n, "NumberOfCells " + str(static_cast<std::int64_t>(n)));
        std::int64_t at = 0;
        f.first.assign(n, -1);
        f.end.assign(n, -1);
        for (std::size_t i = 0; i < n; ++i) {
            const bool polyhedron = kinds[i].type == CellType::polyhedron;
            if (!polyhedron) {
                if (ends[i] != -1 && ends[i] != at)
                    vtu::fail_at(enc_, offsets_ref, "-1 for cell " + str(static_cast<std::int64_t>(i)) + ", not a polyhedron",
                                 str(ends[i]));
                continue;
            }
            if (ends[i] < at + 5)  // a face count and at least 4 faces... of at least 3 nodes: checked below
                vtu::fail_at(enc_, offsets_ref,
                             "the end of polyhedron " + str(static_cast<std::int64_t>(i)) + "'s faces after " + str(at),
                             str(ends[i]));
            f.first[i] = at;
            f.end[i] = at = ends[i];
        }
        f.stream = vtu::read_integers(enc_, f.ref, static_cast<std::size_t>(at), "the last of faceoffsets, " + str(at));
        for (std::size_t i = 0; i < n; ++i) {
            if (f.first[i] < 0) continue;
            const std::string cell = "polyhedron " + str(static_cast<std::int64_t>(i));
            std::int64_t k = f.first[i];
            const std::int64_t count = f.stream[static_cast<std::size_t>(k++)];
            if (count < 4) vtu::fail_at(enc_, f.ref, "at least 4 faces of " + cell, str(count));
            for (std::int64_t face = 0; face < count; ++face) {
                if (k >= f.end[i]) vtu::fail_at(enc_, f.ref, str(count) + " faces of " + cell, "the end of its faces after " + str(face));
                const std::int64_t size = f.stream[static_cast<std::size_t>(k++)];
                if (size < 3 || size > f.end[i] - k)
                    vtu::fail_at(enc_, f.ref, "a face of 3 or more nodes within the faces of " + cell, str(size) + " nodes");
                for (std::int64_t j = 0; j < size; ++j, ++k) {
                    const std::int64_t v = f.stream[static_cast<std::size_t>(k)];
                    if (v < 0 || v >= num_points)
                        vtu::fail_at(enc_, f.ref, "node ids from 0 to " + str(num_points - 1) + " in the faces of " + cell, str(v));
                }
            }
            if (k != f.end[i])
                vtu::fail_at(enc_, f.ref, "the faces of " + cell + " to end at its faceoffset " + str(f.end[i]), "value " + str(k));
        }
        return f;
    }

    /// Polyhedron i of a piece from its face stream, the faces turned out of
    /// it; its point list (`listed`) must hold the faces' nodes.
    void polyhedron_of(const PolyhedronFaces& f, std::size_t i, std::span<const std::int64_t> listed, NodeId first_point,
                       const std::vector<double>& xyz, ElementList& out) const {
        std::vector<NodeId> rings;
        std::vector<int> sizes;
        const std::string cell = "polyhedron " + str(static_cast<std::int64_t>(i));
        std::int64_t k = f.first[i] + 1;
        while (k < f.end[i]) {
            const auto size = static_cast<int>(f.stream[static_cast<std::size_t>(k++)]);
            sizes.push_back(size);
            for (int j = 0; j < size; ++j, ++k) {
                const std::int64_t v = f.stream[static_cast<std::size_t>(k)];
                if (std::find(listed.begin(), listed.end(), v) == listed.end())
                    vtu::fail_at(enc_, f.ref, "faces of " + cell + " on the points its connectivity lists", "node " + str(v));
                rings.push_back(first_point + static_cast<NodeId>(v));
            }
        }
        if (const auto why = orient_polyhedron_faces(rings, sizes, xyz))
            vtu::fail_at(enc_, f.ref, "faces that close " + cell, *why);
        out.push_polyhedron(rings, sizes);
    }

    /// dgwarp's markers from the grid's <FieldData>; false when it holds none.
    bool read_dgwarp_markers(const xml::Element& grid, std::int64_t num_points, Mesh& mesh) const {
        const xml::Element* field = optional_child(grid, "FieldData");
        if (!field) return false;
        const xml::Element* arrays[4];
        int present = 0;
        for (int k = 0; k < 4; ++k) present += (arrays[k] = array_named(*field, marker_arrays[k])) != nullptr;
        if (present == 0) return false;
        for (int k = 0; k < 4; ++k)
            if (!arrays[k])
                fail(*field, std::string("the array ") + marker_arrays[k] + " beside the other dgwarp_marker arrays",
                     "none");
        const vtu::ArrayRef names_ref{arrays[0], "DataArray 'dgwarp_marker_names' of <FieldData>"};
        const vtu::ArrayRef sizes_ref{arrays[1], "DataArray 'dgwarp_marker_sizes' of <FieldData>"};
        const vtu::ArrayRef types_ref{arrays[2], "DataArray 'dgwarp_marker_types' of <FieldData>"};
        const vtu::ArrayRef conn_ref{arrays[3], "DataArray 'dgwarp_marker_connectivity' of <FieldData>"};
        const std::int64_t num_markers = count_attribute(*arrays[1], "NumberOfTuples", std::numeric_limits<std::int64_t>::max());
        const std::string markers_reason = "NumberOfTuples " + str(num_markers) + " of dgwarp_marker_sizes";
        const std::vector<std::string> names =
            vtu::read_strings(enc_, names_ref, static_cast<std::size_t>(num_markers), markers_reason);
        const std::vector<std::int64_t> sizes =
            vtu::read_integers(enc_, sizes_ref, static_cast<std::size_t>(num_markers), markers_reason);
        std::int64_t num_elements = 0;
        for (std::size_t m = 0; m < sizes.size(); ++m) {
            if (sizes[m] < 0 || sizes[m] > std::numeric_limits<std::int64_t>::max() - num_elements)
                vtu::fail_at(enc_, sizes_ref, "element counts >= 0", str(sizes[m]) + " (marker '" + names[m] + "')");
            num_elements += sizes[m];
        }
        const std::vector<std::int64_t> types = vtu::read_integers(
            enc_, types_ref, static_cast<std::size_t>(num_elements), "the sum of dgwarp_marker_sizes");
        std::vector<CellType> kinds(types.size());
        // Each element's end in the connectivity: from its type, or (polygons:
        // any number of nodes) from dgwarp_marker_offsets.
        std::vector<std::int64_t> ends(types.size());
        const xml::Element* offsets_array = array_named(*field, "dgwarp_marker_offsets");
        const vtu::ArrayRef offsets_ref{offsets_array, "DataArray 'dgwarp_marker_offsets' of <FieldData>"};
        const std::vector<std::int64_t> given =
            offsets_array ? vtu::read_integers(enc_, offsets_ref, types.size(), "the sum of dgwarp_marker_sizes")
                          : std::vector<std::int64_t>{};
        std::int64_t num_nodes = 0;
        for (std::size_t i = 0; i < types.size(); ++i) {
            const std::optional<CellType> t =
                types[i] >= 0 && types[i] <= 255 ? cell_type_from_vtk_id(static_cast<int>(types[i])) : std::nullopt;
            if (!t || *t == CellType::polyhedron)
                vtu::fail_at(enc_, types_ref, supported_cells, "type " + str(types[i]) + " (element " + str(static_cast<std::int64_t>(i)) + ")");
            kinds[i] = *t;
            if (*t == CellType::polygon && !offsets_array)
                fail(*field, "the array dgwarp_marker_offsets beside marker polygons (type 7)", "none");
            const std::int64_t count = offsets_array ? given[i] - num_nodes : nodes_per_cell(*t);
            if (count < (*t == CellType::polygon ? 3 : std::max(nodes_per_cell(*t), 1)) ||
                (*t != CellType::polygon && count != nodes_per_cell(*t)))
                vtu::fail_at(enc_, offsets_ref, "offsets that give marker element " + str(static_cast<std::int64_t>(i)) + " (" +
                                 std::string(cell_type_name(*t)) + ") its nodes",
                             str(offsets_array ? given[i] : 0));
            num_nodes += count;
            ends[i] = num_nodes;
        }
        const std::vector<std::int64_t> conn = vtu::read_integers(
            enc_, conn_ref, static_cast<std::size_t>(num_nodes), "the node counts of the dgwarp_marker_types");
        std::size_t element = 0, at = 0;
        for (std::size_t m = 0; m < names.size(); ++m) {
            Marker& marker = mesh.markers.emplace_back(Marker{names[m], {}});
            marker.elements.reserve(static_cast<std::size_t>(sizes[m]), 2);
            std::vector<NodeId> nodes;
            for (std::int64_t e = 0; e < sizes[m]; ++e, ++element) {
                const auto count = static_cast<std::size_t>(ends[element]) - at;
                nodes.resize(count);
                for (std::size_t k = 0; k < count; ++k, ++at) {
                    if (conn[at] < 0 || conn[at] >= num_points)
                        vtu::fail_at(enc_, conn_ref,
                                     "node ids from 0 to " + str(num_points - 1) + " (the points of every <Piece>)",
                                     str(conn[at]) + " (value " + str(static_cast<std::int64_t>(at)) + ", marker '" +
                                         names[m] + "')");
                    nodes[k] = static_cast<NodeId>(conn[at]);
                }
                marker.elements.push_back(kinds[element], nodes);
            }
        }
        return true;
    }

    /// meshio's markers: the cells of dimension dim - 1, grouped by their
    /// gmsh:physical tag, named by the <FieldData> array [tag, dim - 1] of
    /// meshio's field_data, else "physical_<tag>".
    void read_physical_markers(const xml::Element& grid, const Cells& cells, int dim, Mesh& mesh) const {
        std::map<std::int64_t, std::string> names;
        if (const xml::Element* field = optional_child(grid, "FieldData"))
            for (std::size_t c : field->children) {
                const xml::Element& a = doc_.elements[c];
                const std::string* name = a.attribute("Name");
                if (a.name != "DataArray" || !name || !vtu::is_integer_array(a)) continue;
                const std::vector<std::int64_t> v =
                    vtu::read_integers(enc_, {&a, "DataArray '" + *name + "' of <FieldData>"}, std::nullopt, "");
                if (v.size() == 2 && v[1] == dim - 1) names.emplace(v[0], *name);
            }
        std::map<std::int64_t, std::size_t> marker_of_tag;
        for (std::size_t i = 0; i < cells.elements.size(); ++i)
            if (cell_dimension(cells.elements.types[i]) == dim - 1) marker_of_tag.emplace(cells.physical[i], 0);
        for (auto& [tag, m] : marker_of_tag) {
            m = mesh.markers.size();
            const auto name = names.find(tag);
            mesh.markers.push_back({name != names.end() ? name->second : "physical_" + str(tag), {}});
        }
        for (std::size_t i = 0; i < cells.elements.size(); ++i)
            if (cell_dimension(cells.elements.types[i]) == dim - 1)
                copy_element(cells.elements, i, mesh.markers[marker_of_tag.at(cells.physical[i])].elements);
    }

    Mesh assemble(const xml::Element& grid, std::vector<double> xyz, Cells cells) {
        int dim = -1;
        for (CellType t : cells.elements.types) dim = std::max(dim, cell_dimension(t));
        if (dim < 2)
            throw MeshError(file_ + ": the grid has no 2D or 3D cells (highest cell dimension: " + str(dim) +
                            "); dgwarp needs a surface or volume mesh");
        Mesh mesh;
        mesh.dim = dim;
        const std::size_t n = xyz.size() / 3;
        if (dim == 2) {
            // dgwarp's 2D points have no z: the mesh must lie in the z = 0 plane.
            for (std::size_t i = 0; i < n; ++i)
                if (xyz[3 * i + 2] != 0)
                    throw MeshError(file_ + ": the cells are 2D, so this is a 2D mesh, but point " + str(static_cast<std::int64_t>(i)) +
                                        " has z = " + number_text(xyz[3 * i + 2]) +
                                        "; dgwarp reads 2D meshes only in the z = 0 plane (surface meshes in 3D are "
                                        "not supported)",
                                    "", static_cast<std::int64_t>(i));
            mesh.points.resize(2 * n);
            for (std::size_t i = 0; i < n; ++i) {
                mesh.points[2 * i] = xyz[3 * i];
                mesh.points[2 * i + 1] = xyz[3 * i + 1];
            }
        } else {
            mesh.points = std::move(xyz);
        }
        // The cells of the highest dimension, in file order; the others are
        // boundary elements of meshio's markers or are dropped.
        for (std::size_t i = 0; i < cells.elements.size(); ++i)
            if (cell_dimension(cells.elements.types[i]) == dim) copy_element(cells.elements, i, mesh.cells);
        if (!read_dgwarp_markers(grid, static_cast<std::int64_t>(n), mesh) && cells.physical_complete &&
            !cells.physical.empty())
            read_physical_markers(grid, cells, dim, mesh);
        validate(mesh);
        report(1.0);
        return mesh;
    }

    const std::string& file_;
    std::string_view content_;
    ProgressFn progress_;
    double reported_ = -1;
    xml::Document doc_;
    vtu::Encoding enc_;
    std::int64_t piece_count_ = 0;
};

}  // namespace

Mesh read_vtu_text(const std::string& file_name, std::string content) {
    return VtuReader(file_name, content, {}).read();
}

Mesh read_vtu(const std::filesystem::path& path, const ProgressFn& progress) {
    const FileBytes content = FileBytes::read(path);
    const std::string file = path.string();
    return VtuReader(file, content.view(), progress).read();
}

}  // namespace dgwarp
