#include <algorithm>
#include <bit>
#include <cstdint>
#include <cstring>
#include <string>
#include <string_view>
#include <vector>

#include "dgwarp/core/error.hpp"
#include "dgwarp/io/atomic_write.hpp"
#include "dgwarp/io/base64.hpp"
#include "dgwarp/io/vtu.hpp"

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

/// Writes one inline binary DataArray of `count` values of type T, the i-th
/// being value_of(i): base64 of [UInt64 byte count][values].
template <class T, class ValueOf>
void write_data_array(std::ostream& out, std::string_view vtk_type, std::string_view escaped_name,
                      int components, std::size_t count, ValueOf value_of) {
    out << "        <DataArray type=\"" << vtk_type << "\" Name=\"" << escaped_name
        << "\" NumberOfComponents=\"" << components << "\" format=\"binary\">\n          ";
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
    out << "\n        </DataArray>\n";
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
        write_data_array<double>(out, "Float64", escaped_names[f], fields[f].components, values.size(),
                                 [&](std::size_t i) { return values[i]; });
    }
    out << "      </" << section << ">\n";
}

}  // namespace

void write_vtu(std::ostream& out, const Mesh& mesh, const MeshFields& fields) {
    // Check everything before writing anything.
    validate(mesh);
    const std::size_t num_points = mesh.num_points();
    const std::size_t num_cells = mesh.cells.size();
    std::vector<std::string> point_names, cell_names;
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
           "  <UnstructuredGrid>\n"
        << "    <Piece NumberOfPoints=\"" << num_points << "\" NumberOfCells=\"" << num_cells << "\">\n";
    write_fields(out, "PointData", fields.point_data, point_names);
    write_fields(out, "CellData", fields.cell_data, cell_names);

    out << "      <Points>\n";
    const double* p = mesh.points.data();
    if (mesh.dim == 3)
        write_data_array<double>(out, "Float64", "Points", 3, 3 * num_points,
                                 [p](std::size_t k) { return p[k]; });
    else
        write_data_array<double>(out, "Float64", "Points", 3, 3 * num_points, [p](std::size_t k) {
            const std::size_t c = k % 3;
            return c == 2 ? 0.0 : p[k / 3 * 2 + c];
        });
    out << "      </Points>\n";

    out << "      <Cells>\n";
    const ElementList& cells = mesh.cells;
    write_data_array<std::int64_t>(out, "Int64", "connectivity", 1, cells.nodes.size(),
                                   [&](std::size_t i) { return cells.nodes[i]; });
    write_data_array<std::int64_t>(out, "Int64", "offsets", 1, num_cells,
                                   [&](std::size_t i) { return cells.offsets[i + 1]; });
    std::uint8_t vtk_id[std::size(all_cell_types)];
    for (CellType t : all_cell_types) vtk_id[static_cast<int>(t)] = static_cast<std::uint8_t>(vtk_cell_id(t));
    write_data_array<std::uint8_t>(out, "UInt8", "types", 1, num_cells,
                                   [&](std::size_t i) { return vtk_id[static_cast<int>(cells.types[i])]; });
    out << "      </Cells>\n"
           "    </Piece>\n"
           "  </UnstructuredGrid>\n"
           "</VTKFile>\n";
}

void write_vtu(const std::filesystem::path& path, const Mesh& mesh, const MeshFields& fields) {
    write_file_atomically(path, [&](std::ostream& out) { write_vtu(out, mesh, fields); });
}

}  // namespace dgwarp
