// Writing CGNS files (cgns.hpp): a whole mesh, or new coordinates into a copy of the file read.
#include <cgnslib.h>

#include <algorithm>
#include <map>
#include <set>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "dgwarp/core/atomic_write.hpp"
#include "dgwarp/core/error.hpp"
#include "dgwarp/io/cgns/cgns.hpp"
#include "dgwarp/io/cgns/cgns_file.hpp"
#include "dgwarp/io/openfoam/openfoam_poly_mesh.hpp"

namespace dgwarp {

namespace {

using cgns::OpenFile;

/// Names of the zone's own children, which a marker's section may not take.
const std::set<std::string> reserved_names = {"Cells", "GridCoordinates", "ZoneBC", "ZoneType", "ZoneGridConnectivity",
                                              "FamilyName", "FlowSolution", "Ordinal"};
/// The NGON_n section of a mesh with polyhedra (its NFACE_n section is "Cells").
constexpr const char* polyhedral_faces_name = "Faces";

/// A section's element type and connectivity (1-based, CGNS node order; type
/// codes before each element's nodes when its elements are of several types).
struct SectionData {
    int type = 0;
    std::vector<cgsize_t> connectivity;
    std::vector<cgsize_t> offsets;  // MIXED, NGON_n, NFACE_n: where each element starts in connectivity, and its end
};

/// cg_section_write, or for a MIXED, NGON_n or NFACE_n section
/// cg_poly_section_write (CGNS 3.4 stores their connectivity with its ElementStartOffset).
int write_section(const OpenFile& f, int B, int Z, const char* name, const SectionData& s, cgsize_t first, cgsize_t last,
                  int* S) {
    const auto type = static_cast<CGNS_ENUMT(ElementType_t)>(s.type);
    if (s.type == CGNS_ENUMV(MIXED) || s.type == CGNS_ENUMV(NGON_n) || s.type == CGNS_ENUMV(NFACE_n))
        return cg_poly_section_write(f.id(), B, Z, name, type, first, last, 0, s.connectivity.data(), s.offsets.data(), S);
    return cg_section_write(f.id(), B, Z, name, type, first, last, 0, s.connectivity.data(), S);
}

bool holds(const ElementList& list, CellType t) { return std::find(list.types.begin(), list.types.end(), t) != list.types.end(); }

/// Elements in order round them (2D cells, faces of a 3D mesh), one of them a
/// polygon: an NGON_n section, triangles and quadrilaterals too (a MIXED
/// section cannot hold NGON_n elements).
SectionData ngon_section_of(const ElementList& list) {
    SectionData s;
    s.type = CGNS_ENUMV(NGON_n);
    s.offsets.push_back(0);
    for (std::size_t i = 0; i < list.size(); ++i) {
        for (NodeId n : list.nodes_of(i)) s.connectivity.push_back(n + 1);
        s.offsets.push_back(static_cast<cgsize_t>(s.connectivity.size()));
    }
    return s;
}

SectionData section_of(const ElementList& list) {
    if (holds(list, CellType::polygon)) return ngon_section_of(list);
    SectionData s;
    bool mixed = false;
    for (std::size_t i = 1; i < list.size() && !mixed; ++i) mixed = list.types[i] != list.types[0];
    s.type = mixed ? CGNS_ENUMV(MIXED) : cgns::element_type(list.types[0]);
    s.connectivity.reserve(list.nodes.size() + (mixed ? list.size() : 0));
    for (std::size_t i = 0; i < list.size(); ++i) {
        const CellType t = list.types[i];
        const auto nodes = list.nodes_of(i);
        if (mixed) s.offsets.push_back(static_cast<cgsize_t>(s.connectivity.size()));
        if (mixed) s.connectivity.push_back(cgns::element_type(t));
        for (int k = 0; k < nodes_per_cell(t); ++k)
            s.connectivity.push_back(nodes[static_cast<std::size_t>(cgns::cgns_index_of_vtk_node(t, k))] + 1);
    }
    if (mixed) s.offsets.push_back(static_cast<cgsize_t>(s.connectivity.size()));
    return s;
}

/// A 3D mesh with polyhedra as CGNS's polyhedral sections: every distinct
/// face once in an NGON_n section (elements 1 to F; the markers' faces first,
/// as the markers have them, then the cells' other faces as the first cell
/// naming them turns them), every cell in an NFACE_n section (elements F + 1
/// to F + C) as its faces' numbers, negative for a face it names turned the
/// other way (CGNS SIDS 7.3: a positive face number's normal points out of
/// the cell). The fixed types' faces are their outward faces (foam::outward_faces).
struct PolyhedralSections {
    SectionData faces, cells;
    std::vector<std::vector<cgsize_t>> marker_faces;  // per marker: its elements' face numbers
};

class FaceTable {
public:
    /// The number (from 1) of the face with this ring: +k when face k runs
    /// the same way round, -k when the other way (`either_way`), a new face otherwise.
    cgsize_t number(std::span<const NodeId> ring, bool either_way) {
        std::vector<NodeId> key(ring.begin(), ring.end());
        std::sort(key.begin(), key.end());
        std::vector<std::int64_t>& same_nodes = by_nodes_[key];
        for (std::int64_t f : same_nodes) {
            const int turn = compare(f, ring);
            if (turn == 1 || (turn == -1 && either_way)) return static_cast<cgsize_t>(turn * (f + 1));
        }
        const auto f = static_cast<std::int64_t>(offsets_.size()) - 1;
        for (NodeId n : ring) connectivity_.push_back(n + 1);
        offsets_.push_back(static_cast<cgsize_t>(connectivity_.size()));
        same_nodes.push_back(f);
        return static_cast<cgsize_t>(f + 1);
    }
    SectionData section() && {
        SectionData s;
        s.type = CGNS_ENUMV(NGON_n);
        s.connectivity = std::move(connectivity_);
        s.offsets = std::move(offsets_);
        return s;
    }

private:
    /// 1 when face f is `ring` (from another first node), -1 when it is `ring` turned round, else 0.
    int compare(std::int64_t f, std::span<const NodeId> ring) const {
        const auto begin = static_cast<std::size_t>(offsets_[static_cast<std::size_t>(f)]);
        const std::size_t n = ring.size();
        if (static_cast<std::size_t>(offsets_[static_cast<std::size_t>(f) + 1]) - begin != n) return 0;
        const auto at = [&](std::size_t i) { return static_cast<NodeId>(connectivity_[begin + i % n] - 1); };
        std::size_t p = 0;
        while (p < n && at(p) != ring[0]) ++p;
        if (p == n) return 0;
        bool same = true, turned = true;
        for (std::size_t i = 0; i < n; ++i) {
            same = same && at(p + i) == ring[i];
            turned = turned && at(p + n - i) == ring[i];
        }
        return same ? 1 : turned ? -1 : 0;
    }

    std::map<std::vector<NodeId>, std::vector<std::int64_t>> by_nodes_;
    std::vector<cgsize_t> connectivity_;
    std::vector<cgsize_t> offsets_{0};
};

PolyhedralSections polyhedral_sections_of(const Mesh& mesh) {
    PolyhedralSections out;
    FaceTable faces;
    for (const Marker& m : mesh.markers) {
        out.marker_faces.emplace_back();
        for (std::size_t i = 0; i < m.elements.size(); ++i)
            out.marker_faces.back().push_back(faces.number(m.elements.nodes_of(i), false));
    }
    const ElementList& cells = mesh.cells;
    out.cells.type = CGNS_ENUMV(NFACE_n);
    out.cells.offsets.push_back(0);
    std::vector<NodeId> ring;
    for (std::size_t c = 0; c < cells.size(); ++c) {
        if (cells.types[c] == CellType::polyhedron) {
            const auto [f0, f1] = cells.faces_of(c);
            for (std::int64_t f = f0; f < f1; ++f) out.cells.connectivity.push_back(faces.number(cells.face_nodes_of(f), true));
        } else {
            const auto nodes = cells.nodes_of(c);
            const foam::FaceTable& table = foam::outward_faces(cells.types[c]);
            for (int k = 0; k < table.count; ++k) {
                ring.clear();
                for (int i = 0; i < table.size[k]; ++i) ring.push_back(nodes[static_cast<std::size_t>(table.node[k][i])]);
                out.cells.connectivity.push_back(faces.number(ring, true));
            }
        }
        out.cells.offsets.push_back(static_cast<cgsize_t>(out.cells.connectivity.size()));
    }
    out.faces = std::move(faces).section();
    return out;
}

/// The connectivity values of the NGON_n and NFACE_n sections at most (every face of every cell and marker once).
std::int64_t polyhedral_values_bound(const Mesh& mesh) {
    std::int64_t values = 0;
    const ElementList& cells = mesh.cells;
    for (std::size_t c = 0; c < cells.size(); ++c) {
        if (cells.types[c] == CellType::polyhedron) {
            const auto [f0, f1] = cells.faces_of(c);
            values += (f1 - f0) + cells.face_offsets[static_cast<std::size_t>(f1)] - cells.face_offsets[static_cast<std::size_t>(f0)];
        } else {
            const foam::FaceTable& table = foam::outward_faces(cells.types[c]);
            values += table.count;
            for (int k = 0; k < table.count; ++k) values += table.size[k];
        }
    }
    for (const Marker& m : mesh.markers) values += static_cast<std::int64_t>(m.elements.nodes.size());
    return values;
}

/// What libcgns's HDF5 layer strips from both ends of a node's name (C's
/// isspace): a marker name beginning or ending with one would come back another.
constexpr const char* cgns_name_blanks = " \t\n\v\f\r";


}  // namespace

void check_cgns_writable(const std::filesystem::path& path, const Mesh& mesh) {
    validate(mesh);
    const std::string file = path.string();
    if (mesh.cells.empty()) throw MeshError(file + ": the mesh has no cells; a CGNS zone needs at least one");
    const bool polyhedral = holds(mesh.cells, CellType::polyhedron);
    std::set<std::string> seen;
    for (const Marker& m : mesh.markers) {
        if (m.name.empty() || m.name.size() > 32 || m.name.find('/') != std::string::npos ||
            m.name.find('\0') != std::string::npos || m.name == "." || m.name == ".." ||
            m.name.find_first_not_of(cgns_name_blanks) == std::string::npos)
            throw MeshError(file + ": marker '" + m.name +
                                "' cannot be a CGNS name (1 to 32 characters, not blank, no '/'); rename it",
                            m.name);
        const std::string_view blanks(cgns_name_blanks);
        if (blanks.find(m.name.front()) != std::string_view::npos || blanks.find(m.name.back()) != std::string_view::npos)
            throw MeshError(file + ": marker '" + m.name +
                                "' begins or ends with a blank (a space, tab, line break, ...), which CGNS names drop",
                            m.name);
        if (reserved_names.count(m.name) || (polyhedral && m.name == polyhedral_faces_name))
            throw MeshError(file + ": marker '" + m.name + "' has the name of a node of dgwarp's CGNS zone; rename it",
                            m.name);
        if (!seen.insert(m.name).second) throw MeshError(file + ": two markers are called '" + m.name + "'", m.name);
    }
}

namespace {

/// The base, the zone (`cells` cells) and its coordinates in double precision; B and Z their numbers.
void write_zone_and_points(const OpenFile& f, const Mesh& mesh, cgsize_t cells, int& B, int& Z) {
    const std::size_t n = mesh.num_points();
    int C = 0;
    f.write_check(cg_base_write(f.id(), "Base", mesh.dim, mesh.dim, &B), "the base");
    cgsize_t size[3] = {static_cast<cgsize_t>(n), cells, 0};
    f.write_check(cg_zone_write(f.id(), B, "Zone", size, CGNS_ENUMV(Unstructured), &Z), "the zone");
    static const char* axis_names[] = {"CoordinateX", "CoordinateY", "CoordinateZ"};
    std::vector<double> column(n);
    for (int a = 0; a < mesh.dim; ++a) {
        for (std::size_t i = 0; i < n; ++i) column[i] = mesh.points[i * static_cast<std::size_t>(mesh.dim) + static_cast<std::size_t>(a)];
        f.write_check(cg_coord_write(f.id(), B, Z, CGNS_ENUMV(RealDouble), axis_names[a], column.data(), &C),
                      axis_names[a]);
    }
}

/// A marker without elements: no section or BC can be empty, a boundary
/// family of its name keeps it (read_cgns reads it back).
void write_boundary_family(const OpenFile& f, int B, const Marker& m) {
    int F = 0, FB = 0;
    f.write_check(cg_family_write(f.id(), B, m.name.c_str(), &F), "the family of marker '" + m.name + "'");
    f.write_check(cg_fambc_write(f.id(), B, F, "FamBC", CGNS_ENUMV(BCTypeUserDefined), &FB),
                  "the family BC of marker '" + m.name + "'");
}

/// A mesh with polyhedra (polyhedral_sections_of): the NGON_n section
/// "Faces", the NFACE_n section "Cells", and per marker a BC of its name
/// (BCTypeUserDefined, PointList of its faces' element numbers, GridLocation FaceCenter).
void write_polyhedral(const std::filesystem::path& path, const Mesh& mesh, const PolyhedralSections& sections) {
    write_file_atomically_at(path, [&](const std::filesystem::path& tmp) {
        OpenFile f(tmp, CG_MODE_WRITE, path.string());
        int B = 0, Z = 0, S = 0, BC = 0;
        write_zone_and_points(f, mesh, static_cast<cgsize_t>(mesh.cells.size()), B, Z);
        const auto faces = static_cast<cgsize_t>(sections.faces.offsets.size() - 1);
        f.write_check(write_section(f, B, Z, polyhedral_faces_name, sections.faces, 1, faces, &S), "the faces");
        f.write_check(write_section(f, B, Z, "Cells", sections.cells, faces + 1, faces + static_cast<cgsize_t>(mesh.cells.size()), &S),
                      "the cells");
        for (std::size_t k = 0; k < mesh.markers.size(); ++k) {
            const Marker& m = mesh.markers[k];
            if (m.elements.empty()) {
                write_boundary_family(f, B, m);
                continue;
            }
            const std::vector<cgsize_t>& list = sections.marker_faces[k];
            f.write_check(cg_boco_write(f.id(), B, Z, m.name.c_str(), CGNS_ENUMV(BCTypeUserDefined), CGNS_ENUMV(PointList),
                                        static_cast<cgsize_t>(list.size()), list.data(), &BC),
                          "the BC of marker '" + m.name + "'");
            f.write_check(cg_boco_gridlocation_write(f.id(), B, Z, BC, CGNS_ENUMV(FaceCenter)),
                          "the GridLocation of the BC of marker '" + m.name + "'");
        }
        f.close();
    });
}

}  // namespace

void write_cgns(const std::filesystem::path& path, const Mesh& mesh) {
    check_cgns_writable(path, mesh);
    const std::size_t n = mesh.num_points();
    if (n > static_cast<std::size_t>(std::numeric_limits<cgsize_t>::max()))
        throw MeshError(path.string() + ": too many points for this libcgns (32-bit sizes)");
    if (holds(mesh.cells, CellType::polyhedron)) {
        if (polyhedral_values_bound(mesh) >= std::numeric_limits<cgsize_t>::max())
            throw MeshError(path.string() + ": too many faces for this libcgns (32-bit sizes)");
        write_polyhedral(path, mesh, polyhedral_sections_of(mesh));
        return;
    }
    const SectionData cells = section_of(mesh.cells);
    std::vector<SectionData> markers;
    for (const Marker& m : mesh.markers) markers.push_back(m.elements.empty() ? SectionData{} : section_of(m.elements));
    write_file_atomically_at(path, [&](const std::filesystem::path& tmp) {
        OpenFile f(tmp, CG_MODE_WRITE, path.string());
        int B = 0, Z = 0, S = 0, BC = 0;
        const auto num_cells = static_cast<cgsize_t>(mesh.cells.size());
        write_zone_and_points(f, mesh, num_cells, B, Z);
        f.write_check(write_section(f, B, Z, "Cells", cells, 1, num_cells, &S), "the cells");
        cgsize_t next = num_cells + 1;
        for (std::size_t k = 0; k < markers.size(); ++k) {
            const Marker& m = mesh.markers[k];
            if (m.elements.empty()) {
                write_boundary_family(f, B, m);
                continue;
            }
            const cgsize_t range[2] = {next, next + static_cast<cgsize_t>(m.elements.size()) - 1};
            f.write_check(write_section(f, B, Z, m.name.c_str(), markers[k], range[0], range[1], &S),
                          "the section of marker '" + m.name + "'");
            f.write_check(cg_boco_write(f.id(), B, Z, m.name.c_str(), CGNS_ENUMV(BCTypeUserDefined), CGNS_ENUMV(PointRange), 2,
                                        range, &BC),
                          "the BC of marker '" + m.name + "'");
            f.write_check(cg_boco_gridlocation_write(f.id(), B, Z, BC,
                                                     mesh.dim == 3 ? CGNS_ENUMV(FaceCenter) : CGNS_ENUMV(EdgeCenter)),
                          "the GridLocation of the BC of marker '" + m.name + "'");
            next = range[1] + 1;
        }
        f.close();
    });
}

void write_cgns_points(const std::filesystem::path& path, const CgnsSource& source, std::span<const double> points) {
    const auto dim = static_cast<std::size_t>(source.dim);
    if (points.size() != source.num_points * dim)
        throw MeshError(path.string() + ": " + std::to_string(points.size()) + " coordinates for the " +
                        std::to_string(source.num_points) + " points of " + std::to_string(dim) + "D " +
                        source.file.string());
    write_file_atomically_at(path, [&](const std::filesystem::path& tmp) {
        std::error_code ec;
        std::filesystem::copy_file(source.file, tmp, std::filesystem::copy_options::overwrite_existing, ec);
        if (ec) throw IoError(source.file.string(), "cannot copy it to " + path.string() + ": " + ec.message());
        OpenFile f(tmp, CG_MODE_MODIFY, path.string());
        for (std::size_t z = 0; z < source.zones.size(); ++z) {
            const CgnsZone& zone = source.zones[z];
            const int Z = static_cast<int>(z) + 1;
            int ncoords = 0;
            f.write_check(cg_ncoords(f.id(), 1, Z, &ncoords), "the coordinates of zone '" + zone.name + "'");
            for (int c = 1; c <= ncoords; ++c) {
                char name[64] = {};
                CGNS_ENUMT(DataType_t) type{};
                f.write_check(cg_coord_info(f.id(), 1, Z, c, &type, name), "the coordinates of zone '" + zone.name + "'");
                const std::string axis = name;
                const std::size_t a = axis == "CoordinateX" ? 0 : axis == "CoordinateY" ? 1 : 2;
                if (a >= dim) continue;  // the z = 0 of a 2D base stays
                std::vector<double> values(zone.points.size());
                for (std::size_t i = 0; i < values.size(); ++i) values[i] = points[static_cast<std::size_t>(zone.points[i]) * dim + a];
                int C = 0;
                if (type == CGNS_ENUMV(RealSingle)) {
                    std::vector<float> single(values.begin(), values.end());
                    f.write_check(cg_coord_write(f.id(), 1, Z, type, name, single.data(), &C), axis + " of zone '" + zone.name + "'");
                } else {
                    f.write_check(cg_coord_write(f.id(), 1, Z, CGNS_ENUMV(RealDouble), name, values.data(), &C),
                                  axis + " of zone '" + zone.name + "'");
                }
            }
        }
        f.close();
    });
}

}  // namespace dgwarp
