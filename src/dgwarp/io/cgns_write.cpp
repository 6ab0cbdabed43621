// Writing CGNS files (cgns.hpp): a whole mesh, or new coordinates into a copy of the file read.
#include <cgnslib.h>

#include <set>
#include <string>
#include <string_view>
#include <vector>

#include "dgwarp/core/atomic_write.hpp"
#include "dgwarp/core/error.hpp"
#include "dgwarp/io/cgns.hpp"
#include "dgwarp/io/cgns_file.hpp"

namespace dgwarp {

namespace {

using cgns::OpenFile;

/// Names of the zone's own children, which a marker's section may not take.
const std::set<std::string> reserved_names = {"Cells", "GridCoordinates", "ZoneBC", "ZoneType", "ZoneGridConnectivity",
                                              "FamilyName", "FlowSolution", "Ordinal"};

/// A section's element type and connectivity (1-based, CGNS node order; type
/// codes before each element's nodes when its elements are of several types).
struct SectionData {
    int type = 0;
    std::vector<cgsize_t> connectivity;
    std::vector<cgsize_t> offsets;  // MIXED: where each element starts in connectivity, and its end
};

/// cg_section_write, or for a MIXED section cg_poly_section_write (CGNS 3.4
/// stores MIXED connectivity with its ElementStartOffset).
int write_section(const OpenFile& f, int B, int Z, const char* name, const SectionData& s, cgsize_t first, cgsize_t last,
                  int* S) {
    const auto type = static_cast<CGNS_ENUMT(ElementType_t)>(s.type);
    if (s.type == CGNS_ENUMV(MIXED))
        return cg_poly_section_write(f.id(), B, Z, name, type, first, last, 0, s.connectivity.data(), s.offsets.data(), S);
    return cg_section_write(f.id(), B, Z, name, type, first, last, 0, s.connectivity.data(), S);
}

SectionData section_of(const ElementList& list) {
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

/// What libcgns's HDF5 layer strips from both ends of a node's name (C's
/// isspace): a marker name beginning or ending with one would come back another.
constexpr const char* cgns_name_blanks = " \t\n\v\f\r";


}  // namespace

void check_cgns_writable(const std::filesystem::path& path, const Mesh& mesh) {
    validate(mesh);
    const std::string file = path.string();
    if (mesh.cells.empty()) throw MeshError(file + ": the mesh has no cells; a CGNS zone needs at least one");
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
        if (reserved_names.count(m.name))
            throw MeshError(file + ": marker '" + m.name + "' has the name of a node of dgwarp's CGNS zone; rename it",
                            m.name);
        if (!seen.insert(m.name).second) throw MeshError(file + ": two markers are called '" + m.name + "'", m.name);
    }
}

void write_cgns(const std::filesystem::path& path, const Mesh& mesh) {
    check_cgns_writable(path, mesh);
    const std::size_t n = mesh.num_points();
    if (n > static_cast<std::size_t>(std::numeric_limits<cgsize_t>::max()))
        throw MeshError(path.string() + ": too many points for this libcgns (32-bit sizes)");
    const SectionData cells = section_of(mesh.cells);
    std::vector<SectionData> markers;
    for (const Marker& m : mesh.markers) markers.push_back(m.elements.empty() ? SectionData{} : section_of(m.elements));
    write_file_atomically_at(path, [&](const std::filesystem::path& tmp) {
        OpenFile f(tmp, CG_MODE_WRITE, path.string());
        int B = 0, Z = 0, S = 0, C = 0, BC = 0;
        f.write_check(cg_base_write(f.id(), "Base", mesh.dim, mesh.dim, &B), "the base");
        cgsize_t size[3] = {static_cast<cgsize_t>(n), static_cast<cgsize_t>(mesh.cells.size()), 0};
        f.write_check(cg_zone_write(f.id(), B, "Zone", size, CGNS_ENUMV(Unstructured), &Z), "the zone");
        static const char* axis_names[] = {"CoordinateX", "CoordinateY", "CoordinateZ"};
        std::vector<double> column(n);
        for (int a = 0; a < mesh.dim; ++a) {
            for (std::size_t i = 0; i < n; ++i) column[i] = mesh.points[i * static_cast<std::size_t>(mesh.dim) + static_cast<std::size_t>(a)];
            f.write_check(cg_coord_write(f.id(), B, Z, CGNS_ENUMV(RealDouble), axis_names[a], column.data(), &C),
                          axis_names[a]);
        }
        f.write_check(write_section(f, B, Z, "Cells", cells, 1, size[1], &S), "the cells");
        cgsize_t next = size[1] + 1;
        for (std::size_t k = 0; k < markers.size(); ++k) {
            const Marker& m = mesh.markers[k];
            if (m.elements.empty()) {
                // No section or BC can be empty: a boundary family of its name keeps it (read_cgns reads it back).
                int F = 0, FB = 0;
                f.write_check(cg_family_write(f.id(), B, m.name.c_str(), &F), "the family of marker '" + m.name + "'");
                f.write_check(cg_fambc_write(f.id(), B, F, "FamBC", CGNS_ENUMV(BCTypeUserDefined), &FB),
                              "the family BC of marker '" + m.name + "'");
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
