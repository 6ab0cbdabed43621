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
#include "dgwarp/io/vtk_xml.hpp"
#include "dgwarp/io/vtu.hpp"
#include "dgwarp/io/vtu_data_array.hpp"

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
    "a linear VTK cell type (1 vertex, 3 line, 5 triangle, 8 pixel, 9 quad, 10 tetra, 11 voxel, 12 hexahedron, "
    "13 wedge, 14 pyramid)";

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
            if (offsets[i] < end || offsets[i] - end != nodes)
                vtu::fail_at(enc_, offsets_ref,
                             "offsets that give cell " + str(static_cast<std::int64_t>(i)) + " (VTK type " + str(types[i]) + ", " +
                                 std::string(cell_type_name(k->type)) + ") its " + str(nodes) + " nodes",
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

        cells.elements.reserve(cells.elements.size() + n, 4);
        NodeId nodes[8];
        for (std::size_t i = 0; i < n; ++i) {
            const int count = nodes_per_cell(kinds[i].type);
            const std::int64_t* c = conn.data() + (offsets[i] - count);
            for (int k = 0; k < count; ++k)
                nodes[k] = static_cast<NodeId>(first_point) + static_cast<NodeId>(c[kinds[i].order ? kinds[i].order[k] : k]);
            cells.elements.push_back(kinds[i].type, {nodes, static_cast<std::size_t>(count)});
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
        std::int64_t num_nodes = 0;
        for (std::size_t i = 0; i < types.size(); ++i) {
            const std::optional<CellType> t =
                types[i] >= 0 && types[i] <= 255 ? cell_type_from_vtk_id(static_cast<int>(types[i])) : std::nullopt;
            if (!t) vtu::fail_at(enc_, types_ref, supported_cells, "type " + str(types[i]) + " (element " + str(static_cast<std::int64_t>(i)) + ")");
            kinds[i] = *t;
            num_nodes += nodes_per_cell(*t);
        }
        const std::vector<std::int64_t> conn = vtu::read_integers(
            enc_, conn_ref, static_cast<std::size_t>(num_nodes), "the node counts of the dgwarp_marker_types");
        std::size_t element = 0, at = 0;
        for (std::size_t m = 0; m < names.size(); ++m) {
            Marker& marker = mesh.markers.emplace_back(Marker{names[m], {}});
            marker.elements.reserve(static_cast<std::size_t>(sizes[m]), 2);
            NodeId nodes[8];
            for (std::int64_t e = 0; e < sizes[m]; ++e, ++element) {
                const int count = nodes_per_cell(kinds[element]);
                for (int k = 0; k < count; ++k, ++at) {
                    if (conn[at] < 0 || conn[at] >= num_points)
                        vtu::fail_at(enc_, conn_ref,
                                     "node ids from 0 to " + str(num_points - 1) + " (the points of every <Piece>)",
                                     str(conn[at]) + " (value " + str(static_cast<std::int64_t>(at)) + ", marker '" +
                                         names[m] + "')");
                    nodes[k] = static_cast<NodeId>(conn[at]);
                }
                marker.elements.push_back(kinds[element], {nodes, static_cast<std::size_t>(count)});
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
                mesh.markers[marker_of_tag.at(cells.physical[i])].elements.push_back(cells.elements.types[i],
                                                                                     cells.elements.nodes_of(i));
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
            if (cell_dimension(cells.elements.types[i]) == dim)
                mesh.cells.push_back(cells.elements.types[i], cells.elements.nodes_of(i));
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
    const std::string content = read_file_text(path);
    const std::string file = path.string();
    return VtuReader(file, content, progress).read();
}

}  // namespace dgwarp
