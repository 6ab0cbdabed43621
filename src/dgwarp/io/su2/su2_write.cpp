// Writer of SU2 native ASCII meshes, in the layout SU2 itself writes: one
// element per line with its index last, one point per line with its index last,
// tab-separated, numbers in shortest exact form so that reading back is exact.
#include <ostream>
#include <sstream>
#include <string_view>

#include "dgwarp/core/atomic_write.hpp"
#include "dgwarp/core/error.hpp"
#include "dgwarp/io/number_text.hpp"
#include "dgwarp/io/su2/su2.hpp"
#include "dgwarp/io/text_rows.hpp"
#include "dgwarp/io/text_reader.hpp"

namespace dgwarp {

namespace {

/// A marker name must survive `MARKER_TAG= name` and the reader's trimming.
void check_marker_names(const Mesh& mesh) {
    for (std::size_t m = 0; m < mesh.markers.size(); ++m) {
        const std::string& name = mesh.markers[m].name;
        if (name.empty() || trim(name) != name || name.find_first_of("\n\r") != std::string::npos)
            throw MeshError("marker " + std::to_string(m) + " has the name '" + name +
                                "', which SU2 cannot store (it must be non-empty, on one line, without "
                                "surrounding blanks)",
                            name, static_cast<std::int64_t>(m));
        for (std::size_t k = 0; k < m; ++k)
            if (mesh.markers[k].name == name)
                throw MeshError("two markers are called '" + name + "'", name, static_cast<std::int64_t>(m));
    }
}

/// One element per line: SU2 type id, node ids, then (SU2 writes it for
/// volume cells, not for boundary elements) the element index.
void write_elements(std::ostream& out, const ElementList& elements, bool with_index) {
    write_rows(out, static_cast<std::int64_t>(elements.size()), [&](std::int64_t i, RowText& text) {
        const auto k = static_cast<std::size_t>(i);
        append_number(text, static_cast<long long>(vtk_cell_id(elements.types[k])));
        for (NodeId n : elements.nodes_of(k)) {
            text.push_back('\t');
            append_number(text, static_cast<long long>(n));
        }
        if (with_index) {
            text.push_back('\t');
            append_number(text, static_cast<long long>(i));
        }
        text.push_back('\n');
    });
}

}  // namespace

void check_su2_writable(const Mesh& mesh) {
    validate(mesh);
    check_fixed_cell_types(mesh, "SU2");
    check_marker_names(mesh);
}

void write_su2(std::ostream& out, const Mesh& mesh) {
    check_su2_writable(mesh);
    out << "NDIME= " << mesh.dim << '\n';
    out << "NELEM= " << mesh.cells.size() << '\n';
    write_elements(out, mesh.cells, true);
    const std::size_t n = mesh.num_points();
    const auto dim = static_cast<std::size_t>(mesh.dim);
    out << "NPOIN= " << n << '\n';
    write_rows(out, static_cast<std::int64_t>(n), [&](std::int64_t i, RowText& text) {
        for (std::size_t d = 0; d < dim; ++d) {
            append_number(text, mesh.points[static_cast<std::size_t>(i) * dim + d]);
            text.push_back('\t');
        }
        append_number(text, static_cast<long long>(i));
        text.push_back('\n');
    });
    out << "NMARK= " << mesh.markers.size() << '\n';
    for (const Marker& marker : mesh.markers) {
        out << "MARKER_TAG= " << marker.name << '\n';
        out << "MARKER_ELEMS= " << marker.elements.size() << '\n';
        write_elements(out, marker.elements, false);
    }
}

void write_su2(const std::filesystem::path& path, const Mesh& mesh) {
    write_file_atomically(path, [&mesh](std::ostream& out) { write_su2(out, mesh); });
}

void write_su2(const std::filesystem::path& path, const Mesh& mesh, const Su2Surroundings& surroundings) {
    const auto points = static_cast<std::int64_t>(mesh.num_points());
    const auto cells = static_cast<std::int64_t>(mesh.cells.size());
    if (points != surroundings.num_points || cells != surroundings.num_cells)
        throw MeshError("the mesh has " + std::to_string(points) + " points and " + std::to_string(cells) +
                        " cells, the zone it replaces " + std::to_string(surroundings.num_points) + " and " +
                        std::to_string(surroundings.num_cells) + ": it is not that zone");
    check_su2_writable(mesh);
    write_file_atomically(path, [&](std::ostream& out) {
        out << surroundings.before;
        if (surroundings.zone_has_ndime) {
            write_su2(out, mesh);
        } else {  // the dimension comes from the file's header: the zone's text without its NDIME= line
            std::ostringstream zone;
            write_su2(zone, mesh);
            const std::string text = std::move(zone).str();
            out << std::string_view(text).substr(text.find('\n') + 1);
        }
        out << surroundings.after;
    });
}

}  // namespace dgwarp
