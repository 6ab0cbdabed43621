#include <algorithm>
#include <bit>
#include <cstdint>
#include <cstring>
#include <string>
#include <string_view>
#include <vector>

#include "dgwarp/core/atomic_write.hpp"
#include "dgwarp/core/error.hpp"
#include "dgwarp/io/vtu/base64.hpp"
#include "dgwarp/io/vtu/vtu.hpp"

namespace dgwarp {

namespace {

// The values are copied as the host stores them and declared LittleEndian.
static_assert(std::endian::native == std::endian::little,
              "write_vtu writes host-order bytes and declares them LittleEndian");

// Gathers a DataArray's bytes and writes them base64-encoded in large blocks,
// so that a million-node mesh costs a few hundred stream writes, not one per value.
class Base64Sink {
public:
    explicit Base64Sink(std::ostream& out) : out_(out), text_(base64_encoded_size(block_bytes), '\0') {
        raw_.reserve(block_bytes);
    }

    void append(const void* data, std::size_t num_bytes) {
        const auto* bytes = static_cast<const std::byte*>(data);
        while (num_bytes > 0) {
            const std::size_t take = std::min(num_bytes, block_bytes - raw_.size());
            raw_.insert(raw_.end(), bytes, bytes + take);
            bytes += take;
            num_bytes -= take;
            if (raw_.size() == block_bytes) flush();
        }
    }

    /// Encodes what is left, with padding; the sink is empty afterwards.
    void finish() { flush(); }

private:
    // A multiple of 3, so that only the last block of an array can be padded.
    static constexpr std::size_t block_bytes = 3 << 16;

    void flush() {
        const std::size_t n = base64_encode(raw_, text_.data());
        out_.write(text_.data(), static_cast<std::streamsize>(n));
        raw_.clear();
    }

    std::ostream& out_;
    std::vector<std::byte> raw_;
    std::string text_;
};

/// The opening tag of an array: `tag` (DataArray, or Array for strings), its
/// type, name and further attributes.
struct ArrayTag {
    std::string_view tag = "DataArray";
    std::string_view vtk_type;
    std::string_view escaped_name;
    int components = 1;
    std::int64_t tuples = -1;  // NumberOfTuples, written when >= 0 (FieldData arrays)
};

/// Writes one inline binary array of `count` values of type T, the i-th
/// being value_of(i): base64 of [UInt64 byte count][values].
template <class T, class ValueOf>
void write_data_array(std::ostream& out, const ArrayTag& a, std::size_t count, ValueOf value_of) {
    out << "        <" << a.tag << " type=\"" << a.vtk_type << "\" Name=\"" << a.escaped_name << "\"";
    if (a.tag == "DataArray") out << " NumberOfComponents=\"" << a.components << "\"";
    if (a.tuples >= 0) out << " NumberOfTuples=\"" << a.tuples << "\"";
    out << " format=\"binary\">\n          ";
    Base64Sink sink(out);
    const std::uint64_t num_bytes = count * sizeof(T);
    sink.append(&num_bytes, sizeof num_bytes);
    constexpr std::size_t batch = 8192;
    T values[batch];
    for (std::size_t first = 0; first < count; first += batch) {
        const std::size_t n = std::min(batch, count - first);
        for (std::size_t j = 0; j < n; ++j) values[j] = static_cast<T>(value_of(first + j));
        sink.append(values, n * sizeof(T));
    }
    sink.finish();
    out << "\n        </" << a.tag << ">\n";
}

/// `name` escaped for an XML attribute value. Tab, newline and carriage
/// return become character references (a parser would turn them into spaces);
/// other control characters cannot appear in XML 1.0 at all.
std::string escaped_attribute(const std::string& name) {
    std::string s;
    s.reserve(name.size());
    for (const char c : name) {
        switch (c) {
            case '&': s += "&amp;"; break;
            case '<': s += "&lt;"; break;
            case '>': s += "&gt;"; break;
            case '"': s += "&quot;"; break;
            case '\'': s += "&apos;"; break;
            case '\t': s += "&#9;"; break;
            case '\n': s += "&#10;"; break;
            case '\r': s += "&#13;"; break;
            default:
                if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f)
                    throw MeshError("field '" + name + "': its name has control character " +
                                    std::to_string(static_cast<int>(c)) + ", which XML cannot hold");
                s += c;
        }
    }
    return s;
}

/// Throws MeshError naming the field when its size does not fit `count` items.
void check_field(const Field& field, std::size_t count, const char* items) {
    if (field.components < 1)
        throw MeshError("field '" + field.name + "' has " + std::to_string(field.components) +
                        " components, expected at least 1");
    const std::size_t expected = count * static_cast<std::size_t>(field.components);
    if (field.values.size() != expected)
        throw MeshError("field '" + field.name + "' has " + std::to_string(field.values.size()) +
                        " values, expected " + std::to_string(expected) + " (" + std::to_string(count) +
                        " " + items + " × " + std::to_string(field.components) + " components)");
}

void write_fields(std::ostream& out, const char* section, const std::vector<Field>& fields,
                  const std::vector<std::string>& escaped_names) {
    out << "      <" << section << ">\n";
    for (std::size_t f = 0; f < fields.size(); ++f) {
        const auto& values = fields[f].values;
        write_data_array<double>(out, {.vtk_type = "Float64", .escaped_name = escaped_names[f],
                                       .components = fields[f].components},
                                 values.size(), [&](std::size_t i) { return values[i]; });
    }
    out << "      </" << section << ">\n";
}

/// Throws MeshError when a marker name cannot be stored: names are 0-terminated.
void check_marker_names(const Mesh& mesh) {
    for (std::size_t m = 0; m < mesh.markers.size(); ++m)
        if (mesh.markers[m].name.find('\0') != std::string::npos)
            throw MeshError("marker " + std::to_string(m) + ": its name holds a 0 byte, which a VTU file cannot store",
                            mesh.markers[m].name, static_cast<std::int64_t>(m));
}

/// The markers as the FieldData of the grid (see vtu.hpp): names, element
/// counts, element types and node ids.
void write_markers(std::ostream& out, const Mesh& mesh) {
    if (mesh.markers.empty()) return;
    std::string names;
    std::size_t num_elements = 0, num_nodes = 0;
    for (const Marker& m : mesh.markers) {
        names += m.name;
        names += '\0';
        num_elements += m.elements.size();
        num_nodes += m.elements.nodes.size();
    }
    // Every marker's elements, marker after marker.
    std::vector<std::uint8_t> types;
    std::vector<NodeId> nodes;
    types.reserve(num_elements);
    nodes.reserve(num_nodes);
    for (const Marker& m : mesh.markers) {
        for (CellType t : m.elements.types) types.push_back(static_cast<std::uint8_t>(vtk_cell_id(t)));
        nodes.insert(nodes.end(), m.elements.nodes.begin(), m.elements.nodes.end());
    }
    const auto num_markers = static_cast<std::int64_t>(mesh.markers.size());
    out << "    <FieldData>\n";
    // The names as bytes (UInt8, each name ended by a 0 byte), not a String
    // array: meshio cannot read String arrays, and would refuse the whole file.
    write_data_array<char>(out, {.vtk_type = "UInt8", .escaped_name = "dgwarp_marker_names",
                                 .tuples = static_cast<std::int64_t>(names.size())},
                           names.size(), [&](std::size_t i) { return names[i]; });
    write_data_array<std::int64_t>(out, {.vtk_type = "Int64", .escaped_name = "dgwarp_marker_sizes", .tuples = num_markers},
                                   mesh.markers.size(), [&](std::size_t i) { return mesh.markers[i].elements.size(); });
    write_data_array<std::uint8_t>(out, {.vtk_type = "UInt8", .escaped_name = "dgwarp_marker_types",
                                         .tuples = static_cast<std::int64_t>(types.size())},
                                   types.size(), [&](std::size_t i) { return types[i]; });
    write_data_array<std::int64_t>(out, {.vtk_type = "Int64", .escaped_name = "dgwarp_marker_connectivity",
                                         .tuples = static_cast<std::int64_t>(nodes.size())},
                                   nodes.size(), [&](std::size_t i) { return nodes[i]; });
    // Polygons have any number of nodes: then each element's end in the connectivity too.
    bool polygons = false;
    for (const Marker& m : mesh.markers)
        polygons = polygons || std::find(m.elements.types.begin(), m.elements.types.end(), CellType::polygon) !=
                                   m.elements.types.end();
    if (polygons) {
        std::vector<std::int64_t> ends;
        ends.reserve(num_elements);
        std::int64_t base = 0;
        for (const Marker& m : mesh.markers) {
            for (std::size_t e = 0; e < m.elements.size(); ++e) ends.push_back(base + m.elements.offsets[e + 1]);
            base += m.elements.offsets.back();
        }
        write_data_array<std::int64_t>(out, {.vtk_type = "Int64", .escaped_name = "dgwarp_marker_offsets",
                                             .tuples = static_cast<std::int64_t>(ends.size())},
                                       ends.size(), [&](std::size_t i) { return ends[i]; });
    }
    out << "    </FieldData>\n";
}

}  // namespace

void write_vtu(std::ostream& out, const Mesh& mesh, const MeshFields& fields) {
    // Check everything before writing anything.
    validate(mesh);
    const std::size_t num_points = mesh.num_points();
    const std::size_t num_cells = mesh.cells.size();
    std::vector<std::string> point_names, cell_names;
    check_marker_names(mesh);
    for (const Field& f : fields.point_data) {
        check_field(f, num_points, "points");
        point_names.push_back(escaped_attribute(f.name));
    }
    for (const Field& f : fields.cell_data) {
        check_field(f, num_cells, "cells");
        cell_names.push_back(escaped_attribute(f.name));
    }

    out << "<?xml version=\"1.0\"?>\n"
           "<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" byte_order=\"LittleEndian\" "
           "header_type=\"UInt64\">\n"
           "  <UnstructuredGrid>\n";
    write_markers(out, mesh);
    out << "    <Piece NumberOfPoints=\"" << num_points << "\" NumberOfCells=\"" << num_cells << "\">\n";
    write_fields(out, "PointData", fields.point_data, point_names);
    write_fields(out, "CellData", fields.cell_data, cell_names);

    out << "      <Points>\n";
    const double* p = mesh.points.data();
    const ArrayTag points_tag{.vtk_type = "Float64", .escaped_name = "Points", .components = 3};
    if (mesh.dim == 3)
        write_data_array<double>(out, points_tag, 3 * num_points, [p](std::size_t k) { return p[k]; });
    else
        write_data_array<double>(out, points_tag, 3 * num_points, [p](std::size_t k) {
            const std::size_t c = k % 3;
            return c == 2 ? 0.0 : p[k / 3 * 2 + c];
        });
    out << "      </Points>\n";

    out << "      <Cells>\n";
    const ElementList& cells = mesh.cells;
    write_data_array<std::int64_t>(out, {.vtk_type = "Int64", .escaped_name = "connectivity"}, cells.nodes.size(),
                                   [&](std::size_t i) { return cells.nodes[i]; });
    write_data_array<std::int64_t>(out, {.vtk_type = "Int64", .escaped_name = "offsets"}, num_cells,
                                   [&](std::size_t i) { return cells.offsets[i + 1]; });
    std::uint8_t vtk_id[std::size(all_cell_types)];
    for (CellType t : all_cell_types) vtk_id[static_cast<int>(t)] = static_cast<std::uint8_t>(vtk_cell_id(t));
    write_data_array<std::uint8_t>(out, {.vtk_type = "UInt8", .escaped_name = "types"}, num_cells,
                                   [&](std::size_t i) { return vtk_id[static_cast<int>(cells.types[i])]; });
    if (cells.has_faces()) {
        // Polyhedra as VTK's XML files hold them: per polyhedron a stream of
        // its face count, then each face's node count and nodes, in "faces";
        // per cell the end of its stream in "faceoffsets" (-1 for the others).
        std::vector<std::int64_t> stream, ends(num_cells, -1);
        for (std::size_t c = 0; c < num_cells; ++c) {
            const auto [f0, f1] = cells.faces_of(c);
            if (f1 == f0) continue;
            stream.push_back(f1 - f0);
            for (std::int64_t f = f0; f < f1; ++f) {
                const auto ring = cells.face_nodes_of(f);
                stream.push_back(static_cast<std::int64_t>(ring.size()));
                stream.insert(stream.end(), ring.begin(), ring.end());
            }
            ends[c] = static_cast<std::int64_t>(stream.size());
        }
        write_data_array<std::int64_t>(out, {.vtk_type = "Int64", .escaped_name = "faces"}, stream.size(),
                                       [&](std::size_t i) { return stream[i]; });
        write_data_array<std::int64_t>(out, {.vtk_type = "Int64", .escaped_name = "faceoffsets"}, num_cells,
                                       [&](std::size_t i) { return ends[i]; });
    }
    out << "      </Cells>\n"
           "    </Piece>\n"
           "  </UnstructuredGrid>\n"
           "</VTKFile>\n";
}

void write_vtu(const std::filesystem::path& path, const Mesh& mesh, const MeshFields& fields) {
    write_file_atomically(path, [&](std::ostream& out) { write_vtu(out, mesh, fields); });
}

}  // namespace dgwarp
