// Gmsh writer, MSH 4.1 and 2.2 ASCII.
//
// Layout: physical groups 1..n are the markers (dimension dim - 1, in marker
// order), n + 1 is "domain" (the cells, dimension dim). In 4.1, marker i is
// the curve (2D) or surface (3D) entity i + 1 and the cells the surface or
// volume entity 1, which also holds every node; the 2.2 elementary tags are the
// same. An element in several markers is written once per marker. Node tags
// are 1..N, element tags 1..M. Blocks are runs of one element type, so the
// element order of every marker and of the cells is kept and read_gmsh gives
// back the same Mesh.
#include <algorithm>
#include <array>
#include <string>
#include <utility>
#include <vector>

#include "dgwarp/core/atomic_write.hpp"
#include "dgwarp/core/error.hpp"
#include "dgwarp/io/gmsh/gmsh.hpp"
#include "dgwarp/io/text_rows.hpp"
#include "dgwarp/io/gmsh/gmsh_element_types.hpp"
#include "dgwarp/io/number_text.hpp"

namespace dgwarp {

namespace {

using msh::gmsh_index_of_vtk_node;
using msh::gmsh_type_id;

void write_int(std::ostream& out, std::int64_t v) { write_number(out, static_cast<long long>(v)); }

// Appends `x y z` of node i (z = 0 for a 2D mesh).
void append_point(RowText& s, const Mesh& mesh, std::size_t i) {
    const double* p = mesh.points.data() + i * static_cast<std::size_t>(mesh.dim);
    append_number(s, p[0]);
    s += ' ';
    append_number(s, p[1]);
    s += ' ';
    append_number(s, mesh.dim == 3 ? p[2] : 0.0);
}

// Appends the node tags of element i of `list` in Gmsh order, each preceded by a space.
void append_element_nodes(RowText& s, const ElementList& list, std::size_t i) {
    const CellType t = list.types[i];
    const auto vtk = list.nodes_of(i);
    std::array<NodeId, 8> gmsh{};
    const auto order = gmsh_index_of_vtk_node(t);
    for (std::size_t k = 0; k < vtk.size(); ++k) gmsh[order[k]] = vtk[k];
    for (std::size_t k = 0; k < vtk.size(); ++k) {
        s += ' ';
        append_number(s, static_cast<long long>(gmsh[k]) + 1);
    }
}

void write_header(std::ostream& out, const Mesh& mesh, int version) {
    out << "$MeshFormat\n" << (version == 41 ? "4.1" : "2.2") << " 0 8\n$EndMeshFormat\n";
    const auto n = static_cast<std::int64_t>(mesh.markers.size());
    out << "$PhysicalNames\n";
    write_int(out, n + 1);
    out << '\n';
    for (std::int64_t i = 0; i < n; ++i) {
        out << mesh.dim - 1 << ' ';
        write_int(out, i + 1);
        out << " \"" << mesh.markers[i].name << "\"\n";
    }
    out << mesh.dim << ' ';
    write_int(out, n + 1);
    out << " \"domain\"\n$EndPhysicalNames\n";
}

// Bounding box (min x y z, max x y z) of the nodes of `list`; zeros when empty.
std::array<double, 6> bounding_box(const Mesh& mesh, const ElementList& list) {
    std::array<double, 6> box{};
    bool first = true;
    for (NodeId id : list.nodes) {
        for (int k = 0; k < 3; ++k) {
            const double v = k < mesh.dim ? mesh.points[static_cast<std::size_t>(id) * mesh.dim + k] : 0.0;
            box[k] = first ? v : std::min(box[k], v);
            box[3 + k] = first ? v : std::max(box[3 + k], v);
        }
        first = false;
    }
    return box;
}

void write_entity(std::ostream& out, const Mesh& mesh, const ElementList& list, std::int64_t tag,
                  std::int64_t physical) {
    write_int(out, tag);
    for (double v : bounding_box(mesh, list)) {
        out << ' ';
        write_number(out, v);
    }
    out << " 1 ";
    write_int(out, physical);
    out << " 0\n";  // no bounding entities
}

// Runs of consecutive elements of one type: [begin, end) pairs.
std::vector<std::pair<std::size_t, std::size_t>> type_runs(const ElementList& list) {
    std::vector<std::pair<std::size_t, std::size_t>> runs;
    for (std::size_t i = 0; i < list.size(); ++i)
        if (i == 0 || list.types[i] != list.types[i - 1])
            runs.push_back({i, i + 1});
        else
            runs.back().second = i + 1;
    return runs;
}

void write_41(std::ostream& out, const Mesh& mesh) {
    const auto n = static_cast<std::int64_t>(mesh.markers.size());
    const auto num_points = static_cast<std::int64_t>(mesh.num_points());

    out << "$Entities\n" << (mesh.dim == 3 ? "0 0 " : "0 ");
    write_int(out, n);
    out << (mesh.dim == 3 ? " 1\n" : " 1 0\n");
    for (std::int64_t i = 0; i < n; ++i) write_entity(out, mesh, mesh.markers[i].elements, i + 1, i + 1);
    write_entity(out, mesh, mesh.cells, 1, n + 1);
    out << "$EndEntities\n";

    out << "$Nodes\n";
    if (num_points == 0) {
        out << "0 0 0 0\n";
    } else {
        out << "1 ";
        write_int(out, num_points);
        out << " 1 ";
        write_int(out, num_points);
        out << '\n' << mesh.dim << " 1 0 ";
        write_int(out, num_points);
        out << '\n';
        write_rows(out, num_points, [&](std::int64_t i, RowText& text) {
            append_number(text, static_cast<long long>(i) + 1);
            text += '\n';
        });
        write_rows(out, num_points, [&](std::int64_t i, RowText& text) {
            append_point(text, mesh, static_cast<std::size_t>(i));
            text += '\n';
        });
    }
    out << "$EndNodes\n";

    struct Block {
        int dim;
        std::int64_t entity;
        const ElementList* list;
        std::size_t begin, end;
    };
    std::vector<Block> blocks;
    for (std::int64_t i = 0; i < n; ++i)
        for (auto [b, e] : type_runs(mesh.markers[i].elements))
            blocks.push_back({mesh.dim - 1, i + 1, &mesh.markers[i].elements, b, e});
    for (auto [b, e] : type_runs(mesh.cells)) blocks.push_back({mesh.dim, 1, &mesh.cells, b, e});
    std::int64_t total = 0;
    for (const Block& b : blocks) total += static_cast<std::int64_t>(b.end - b.begin);

    out << "$Elements\n";
    write_int(out, static_cast<std::int64_t>(blocks.size()));
    out << ' ';
    write_int(out, total);
    out << (total > 0 ? " 1 " : " 0 ");
    write_int(out, total);
    out << '\n';
    std::int64_t tag = 0;
    for (const Block& b : blocks) {
        out << b.dim << ' ';
        write_int(out, b.entity);
        out << ' ' << gmsh_type_id(b.list->types[b.begin]) << ' ';
        write_int(out, static_cast<std::int64_t>(b.end - b.begin));
        out << '\n';
        write_rows(out, static_cast<std::int64_t>(b.end - b.begin), [&](std::int64_t k, RowText& text) {
            append_number(text, static_cast<long long>(tag + k) + 1);
            append_element_nodes(text, *b.list, b.begin + static_cast<std::size_t>(k));
            text += '\n';
        });
        tag += static_cast<std::int64_t>(b.end - b.begin);
    }
    out << "$EndElements\n";
}

void write_22(std::ostream& out, const Mesh& mesh) {
    out << "$Nodes\n";
    write_int(out, static_cast<std::int64_t>(mesh.num_points()));
    out << '\n';
    write_rows(out, static_cast<std::int64_t>(mesh.num_points()), [&](std::int64_t i, RowText& text) {
        append_number(text, static_cast<long long>(i) + 1);
        text += ' ';
        append_point(text, mesh, static_cast<std::size_t>(i));
        text += '\n';
    });
    out << "$EndNodes\n";

    const auto n = static_cast<std::int64_t>(mesh.markers.size());
    std::int64_t total = static_cast<std::int64_t>(mesh.cells.size());
    for (const Marker& m : mesh.markers) total += static_cast<std::int64_t>(m.elements.size());
    out << "$Elements\n";
    write_int(out, total);
    out << '\n';
    std::int64_t tag = 0;
    // Each element line: tag type 2 physical elementary nodes...
    auto write_list = [&](const ElementList& list, std::int64_t physical, std::int64_t elementary) {
        write_rows(out, static_cast<std::int64_t>(list.size()), [&](std::int64_t k, RowText& text) {
            const auto i = static_cast<std::size_t>(k);
            append_number(text, static_cast<long long>(tag + k) + 1);
            text += ' ';
            append_number(text, static_cast<long long>(gmsh_type_id(list.types[i])));
            text += " 2 ";
            append_number(text, static_cast<long long>(physical));
            text += ' ';
            append_number(text, static_cast<long long>(elementary));
            append_element_nodes(text, list, i);
            text += '\n';
        });
        tag += static_cast<std::int64_t>(list.size());
    };
    for (std::int64_t i = 0; i < n; ++i) write_list(mesh.markers[i].elements, i + 1, i + 1);
    write_list(mesh.cells, n + 1, 1);
    out << "$EndElements\n";
}

}  // namespace

void check_gmsh_writable(const Mesh& mesh) {
    validate(mesh);
    check_fixed_cell_types(mesh, "Gmsh");
    for (const Marker& m : mesh.markers) {
        if (m.name.find_first_of("\"\n\r") != std::string::npos)
            throw MeshError("marker name '" + m.name + "' cannot be written to a Gmsh file (it contains a double "
                            "quote or a line break)",
                            m.name);
        for (CellType t : m.elements.types)
            if (cell_dimension(t) != mesh.dim - 1)
                throw MeshError("marker '" + m.name + "' has " + std::string(cell_type_name(t)) +
                                    " elements, which the Gmsh writer does not support in a " +
                                    std::to_string(mesh.dim) + "D mesh",
                                m.name);
    }
}

void write_gmsh(std::ostream& out, const Mesh& mesh, int version) {
    if (version != 41 && version != 22)
        throw FormatError("Gmsh MSH version " + std::to_string(version) +
                          " cannot be written; dgwarp writes 41 (MSH 4.1) and 22 (MSH 2.2)");
    check_gmsh_writable(mesh);
    write_header(out, mesh, version);
    if (version == 41)
        write_41(out, mesh);
    else
        write_22(out, mesh);
}

void write_gmsh(const std::filesystem::path& path, const Mesh& mesh, int version) {
    write_file_atomically(path, [&](std::ostream& out) { write_gmsh(out, mesh, version); });
}

}  // namespace dgwarp
