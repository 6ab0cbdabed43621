// Reading CGNS files (cgns.hpp): each zone is read on its own (zone-local
// vertex numbers), then the zones are joined into one mesh.
#include <cgnslib.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>
#include <string>
#include <vector>

#include "dgwarp/core/error.hpp"
#include "dgwarp/io/cgns.hpp"
#include "dgwarp/io/cgns_file.hpp"
#include "dgwarp/io/openfoam_poly_mesh.hpp"

namespace dgwarp {

namespace {

using cgns::OpenFile;

/// The faces (3D) or edges (2D) of `cells` that belong to one cell only,
/// pointing out of it, in cell order.
ElementList exterior_faces(int dim, const ElementList& cells) {
    std::map<std::vector<NodeId>, int> uses;
    std::vector<std::pair<CellType, std::vector<NodeId>>> all;
    for (std::size_t c = 0; c < cells.size(); ++c) {
        const auto nodes = cells.nodes_of(c);
        const CellType t = cells.types[c];
        if (dim == 2) {
            for (std::size_t i = 0; i < nodes.size(); ++i) all.push_back({CellType::line, {nodes[i], nodes[(i + 1) % nodes.size()]}});
        } else {
            const foam::FaceTable& table = foam::outward_faces(t);
            for (int k = 0; k < table.count; ++k) {
                std::vector<NodeId> face;
                for (int i = 0; i < table.size[k]; ++i) face.push_back(nodes[static_cast<std::size_t>(table.node[k][i])]);
                all.push_back({face.size() == 3 ? CellType::triangle : CellType::quadrilateral, face});
            }
        }
    }
    const auto key_of = [](std::vector<NodeId> face) {
        std::sort(face.begin(), face.end());
        return face;
    };
    for (const auto& [type, face] : all) ++uses[key_of(face)];
    ElementList faces;
    for (const auto& [type, face] : all)
        if (uses[key_of(face)] == 1) faces.push_back(type, face);
    return faces;
}

/// A boundary condition of a zone, as the faces it takes (indices into ZoneData::faces).
struct ZoneBoundary {
    std::string marker;  // the family's name, or the BC's
    std::string type;    // its BC type ("BCWall", "BCSymmetryPlane"; a family's when FamilySpecified)
    std::vector<std::int64_t> faces;
};

/// A 1-to-1 vertex connectivity: zone vertex points[i] is vertex donor_points[i] of zone `donor`.
struct ZoneJoin {
    std::string donor;
    std::vector<cgsize_t> points, donor_points;  // 1-based
};

/// One unstructured zone read on its own; node ids are zone vertices (0-based).
struct ZoneData {
    std::string name;
    cgsize_t vertices = 0;
    std::vector<double> points;  // vertices × dim
    ElementList cells;
    ElementList faces;                     // the elements of dimension dim - 1, in file order
    std::vector<cgsize_t> face_numbers;    // each face's element number
    std::vector<int> face_section;         // each face's section (index into section_names)
    std::vector<std::string> section_names;
    std::vector<ZoneBoundary> boundaries;
    std::vector<ZoneJoin> joins;
};

std::string zone_text(const ZoneData& z) { return "zone '" + z.name + "'"; }

/// The most values an array of a file of `file_size` bytes is believed to
/// hold: a guard against counts that would allocate far more than the file
/// could contain (a damaged file), generous enough for compressed data.
std::int64_t most_values(std::uintmax_t file_size) { return 64 * static_cast<std::int64_t>(file_size) + 4096; }

class Reader {
public:
    Reader(const std::filesystem::path& path, OpenFile& file, int dim, std::uintmax_t file_size)
        : path_(path), f_(file), dim_(dim), limit_(most_values(file_size)) {}

    ZoneData read_zone(int z) {
        ZoneData zone;
        char name[64] = {};
        cgsize_t size[9] = {};
        f_.read_check(cg_zone_read(f_.id(), 1, z, name, size), "zone " + std::to_string(z) + " of base 1");
        zone.name = name;
        CGNS_ENUMT(ZoneType_t) type{};
        f_.read_check(cg_zone_type(f_.id(), 1, z, &type), "the type of " + zone_text(zone));
        if (type != CGNS_ENUMV(Unstructured))
            throw FormatError(f_.name() + ": " + zone_text(zone) + " is " +
                              (type == CGNS_ENUMV(Structured) ? "structured" : "of an unknown zone type") +
                              "; dgwarp reads unstructured zones only (element sections)");
        zone.vertices = size[0];
        if (zone.vertices < 1 || zone.vertices > limit_)
            throw ParseError(f_.name(), 0, "a vertex count from 1 to " + std::to_string(limit_) + " in " + zone_text(zone),
                             std::to_string(zone.vertices));
        read_coordinates(z, zone);
        read_sections(z, zone);
        read_boundaries(z, zone);
        read_joins(z, zone);
        return zone;
    }

private:
    void read_coordinates(int z, ZoneData& zone) {
        int ncoords = 0;
        f_.read_check(cg_ncoords(f_.id(), 1, z, &ncoords), "the coordinates of " + zone_text(zone));
        static const char* axis_names[] = {"CoordinateX", "CoordinateY", "CoordinateZ"};
        std::vector<std::string> names;
        for (int c = 1; c <= ncoords; ++c) {
            char cname[64] = {};
            CGNS_ENUMT(DataType_t) type{};
            f_.read_check(cg_coord_info(f_.id(), 1, z, c, &type, cname), "coordinate " + std::to_string(c) + " of " + zone_text(zone));
            names.push_back(cname);
            if (std::find(std::begin(axis_names), std::end(axis_names), names.back()) == std::end(axis_names))
                throw FormatError(f_.name() + ": " + zone_text(zone) + " has coordinate '" + names.back() +
                                  "'; dgwarp reads Cartesian coordinates (CoordinateX, CoordinateY, CoordinateZ) only");
        }
        const cgsize_t one = 1;
        std::vector<double> column(static_cast<std::size_t>(zone.vertices));
        zone.points.assign(static_cast<std::size_t>(zone.vertices) * static_cast<std::size_t>(dim_), 0.0);
        for (int a = 0; a < 3; ++a) {
            const bool present = std::find(names.begin(), names.end(), axis_names[a]) != names.end();
            if (a < dim_ && !present)
                throw ParseError(f_.name(), 0, std::string(axis_names[a]) + " in " + zone_text(zone), "none");
            if (!present) continue;
            f_.read_check(cg_coord_read(f_.id(), 1, z, axis_names[a], CGNS_ENUMV(RealDouble), &one, &zone.vertices,
                                        column.data()),
                          std::string(axis_names[a]) + " of " + zone_text(zone) + " (" + std::to_string(zone.vertices) +
                              " values)");
            for (std::size_t i = 0; i < column.size(); ++i) {
                if (!std::isfinite(column[i]))
                    throw ParseError(f_.name(), 0,
                                     "a finite " + std::string(axis_names[a]) + " of vertex " + std::to_string(i + 1) +
                                         " of " + zone_text(zone),
                                     std::to_string(column[i]));
                if (a < dim_) {
                    zone.points[i * static_cast<std::size_t>(dim_) + static_cast<std::size_t>(a)] = column[i];
                } else if (column[i] != 0.0) {
                    throw FormatError(f_.name() + ": " + zone_text(zone) + " of a 2D base (cell dimension 2) has point " +
                                      std::to_string(i + 1) + " at z = " + std::to_string(column[i]) +
                                      "; dgwarp's 2D meshes lie in the z = 0 plane");
                }
            }
        }
    }

    void read_sections(int z, ZoneData& zone) {
        int nsections = 0;
        f_.read_check(cg_nsections(f_.id(), 1, z, &nsections), "the element sections of " + zone_text(zone));
        for (int s = 1; s <= nsections; ++s) {
            char name[64] = {};
            CGNS_ENUMT(ElementType_t) type{};
            cgsize_t start = 0, end = 0;
            int nbndry = 0, parent_flag = 0;
            f_.read_check(cg_section_read(f_.id(), 1, z, s, name, &type, &start, &end, &nbndry, &parent_flag),
                          "element section " + std::to_string(s) + " of " + zone_text(zone));
            const std::string where = "section '" + std::string(name) + "' of " + zone_text(zone);
            zone.section_names.push_back(name);
            const std::int64_t count = static_cast<std::int64_t>(end) - start + 1;
            if (start < 1 || count < 1 || count > limit_)
                throw ParseError(f_.name(), 0, "an element range from 1 with 1 to " + std::to_string(limit_) +
                                                   " elements in " + where,
                                 std::to_string(start) + " to " + std::to_string(end));
            CellType cell{};
            if (type != CGNS_ENUMV(MIXED) && !cgns::cell_type_of(type, cell))
                throw FormatError(f_.name() + ": " + where + " holds " + cgns::element_type_name(type) +
                                  " elements; dgwarp reads linear elements only (NODE, BAR_2, TRI_3, QUAD_4, TETRA_4, "
                                  "PYRA_5, PENTA_6, HEXA_8, and MIXED sections of them)");
            cgsize_t data_size = 0;
            f_.read_check(cg_ElementDataSize(f_.id(), 1, z, s, &data_size), "the connectivity size of " + where);
            const std::int64_t expected = type == CGNS_ENUMV(MIXED) ? -1 : count * nodes_per_cell(cell);
            if (data_size < 1 || data_size > 9 * count || (expected >= 0 && data_size != expected))
                throw ParseError(f_.name(), 0,
                                 expected >= 0 ? std::to_string(expected) + " connectivity values (" +
                                                     std::to_string(count) + " " + cgns::element_type_name(type) + ") in " + where
                                               : "at most 9 connectivity values an element in " + where,
                                 std::to_string(data_size));
            std::vector<cgsize_t> data(static_cast<std::size_t>(data_size));
            std::vector<cgsize_t> parents(parent_flag ? static_cast<std::size_t>(count) * 4 : 0);
            std::vector<cgsize_t> offsets;  // MIXED sections (CGNS 3.4's ElementStartOffset): where each element starts
            if (type == CGNS_ENUMV(MIXED)) {
                offsets.resize(static_cast<std::size_t>(count) + 1);
                f_.read_check(cg_poly_elements_read(f_.id(), 1, z, s, data.data(), offsets.data(),
                                                    parent_flag ? parents.data() : nullptr),
                              "the connectivity of " + where);
            } else {
                f_.read_check(cg_elements_read(f_.id(), 1, z, s, data.data(), parent_flag ? parents.data() : nullptr),
                              "the connectivity of " + where);
            }
            take_elements(zone, s - 1, where, type, start, count, data, offsets);
        }
    }

    /// Adds a section's elements: cells and faces; other dimensions are left out.
    void take_elements(ZoneData& zone, int section, const std::string& where, int type, cgsize_t start,
                       std::int64_t count, const std::vector<cgsize_t>& data, const std::vector<cgsize_t>& offsets) {
        std::size_t at = 0;
        NodeId nodes[8];
        for (std::int64_t e = 0; e < count; ++e) {
            const std::string element = "element " + std::to_string(start + e) + " of " + where;
            int etype = type;
            if (type == CGNS_ENUMV(MIXED)) {
                if (offsets[static_cast<std::size_t>(e)] != static_cast<cgsize_t>(at))
                    throw ParseError(f_.name(), 0, "ElementStartOffset " + std::to_string(at) + " for " + element,
                                     std::to_string(offsets[static_cast<std::size_t>(e)]));
                if (at >= data.size()) throw ParseError(f_.name(), 0, "the type of " + element, "end of the connectivity");
                etype = static_cast<int>(data[at++]);
            }
            CellType t{};
            if (!cgns::cell_type_of(etype, t))
                throw FormatError(f_.name() + ": " + element + " is " + cgns::element_type_name(etype) +
                                  "; dgwarp reads linear elements only (NODE, BAR_2, TRI_3, QUAD_4, TETRA_4, PYRA_5, "
                                  "PENTA_6, HEXA_8)");
            const int n = nodes_per_cell(t);
            if (at + static_cast<std::size_t>(n) > data.size())
                throw ParseError(f_.name(), 0, std::to_string(n) + " nodes of " + element, "end of the connectivity");
            for (int i = 0; i < n; ++i) {
                const cgsize_t v = data[at + static_cast<std::size_t>(cgns::cgns_index_of_vtk_node(t, i))];
                if (v < 1 || v > zone.vertices)
                    throw ParseError(f_.name(), 0,
                                     "node numbers from 1 to " + std::to_string(zone.vertices) + " in " + element,
                                     std::to_string(v));
                nodes[i] = static_cast<NodeId>(v - 1);
            }
            at += static_cast<std::size_t>(n);
            if (cell_dimension(t) == dim_) {
                zone.cells.push_back(t, {nodes, static_cast<std::size_t>(n)});
            } else if (cell_dimension(t) == dim_ - 1) {
                zone.faces.push_back(t, {nodes, static_cast<std::size_t>(n)});
                zone.face_numbers.push_back(start + static_cast<cgsize_t>(e));
                zone.face_section.push_back(section);
            }
        }
    }

    /// The index in zone.faces of element number `number`, or -1.
    static std::int64_t face_index(const ZoneData& zone, const std::vector<std::int64_t>& order, cgsize_t number) {
        auto it = std::lower_bound(order.begin(), order.end(), number,
                                   [&](std::int64_t i, cgsize_t n) { return zone.face_numbers[static_cast<std::size_t>(i)] < n; });
        if (it == order.end() || zone.face_numbers[static_cast<std::size_t>(*it)] != number) return -1;
        return *it;
    }

    void read_boundaries(int z, ZoneData& zone) {
        int nbocos = 0;
        f_.read_check(cg_nbocos(f_.id(), 1, z, &nbocos), "the boundary conditions of " + zone_text(zone));
        std::vector<std::int64_t> order(zone.faces.size());
        std::iota(order.begin(), order.end(), 0);
        std::sort(order.begin(), order.end(),
                  [&](std::int64_t a, std::int64_t b) { return zone.face_numbers[static_cast<std::size_t>(a)] < zone.face_numbers[static_cast<std::size_t>(b)]; });
        for (int bc = 1; bc <= nbocos; ++bc) {
            char name[64] = {};
            CGNS_ENUMT(BCType_t) bctype{};
            CGNS_ENUMT(PointSetType_t) ptset{};
            cgsize_t npnts = 0, normal_size = 0;
            int normal_index = 0, ndataset = 0;
            CGNS_ENUMT(DataType_t) normal_type{};
            f_.read_check(cg_boco_info(f_.id(), 1, z, bc, name, &bctype, &ptset, &npnts, &normal_index, &normal_size,
                                       &normal_type, &ndataset),
                          "boundary condition " + std::to_string(bc) + " of " + zone_text(zone));
            const std::string where = "BC '" + std::string(name) + "' of " + zone_text(zone);
            CGNS_ENUMT(GridLocation_t) location{};
            f_.read_check(cg_boco_gridlocation_read(f_.id(), 1, z, bc, &location), "the GridLocation of " + where);
            const bool range = ptset == CGNS_ENUMV(PointRange) || ptset == CGNS_ENUMV(ElementRange);
            const bool list = ptset == CGNS_ENUMV(PointList) || ptset == ::ElementList;
            if (!range && !list)
                throw FormatError(f_.name() + ": " + where + " has a point set of type " +
                                  cg_PointSetTypeName(ptset) + "; dgwarp reads PointList, PointRange, ElementList and ElementRange");
            const bool of_elements = ptset == CGNS_ENUMV(ElementRange) || ptset == ::ElementList ||
                                     location == CGNS_ENUMV(FaceCenter) || location == CGNS_ENUMV(EdgeCenter) ||
                                     location == CGNS_ENUMV(CellCenter);
            if (!of_elements && location != CGNS_ENUMV(Vertex))
                throw FormatError(f_.name() + ": " + where + " is located at " + cg_GridLocationName(location) +
                                  "; dgwarp reads BCs on vertices (Vertex) or on face elements (FaceCenter, EdgeCenter)");
            if (npnts < (range ? 2 : 0) || (range && npnts != 2) || npnts > limit_)
                throw ParseError(f_.name(), 0, range ? "2 values (a range) in " + where : "a point count in " + where,
                                 std::to_string(npnts));
            std::vector<cgsize_t> points(static_cast<std::size_t>(npnts));
            if (npnts > 0) f_.read_check(cg_boco_read(f_.id(), 1, z, bc, points.data(), nullptr), "the points of " + where);
            ZoneBoundary b{family_or(z, bc, name), bc_type_name(bctype, family_or(z, bc, "")), {}};
            const cgsize_t upper = of_elements ? std::numeric_limits<cgsize_t>::max() : zone.vertices;
            if (range) {
                if (points[0] < 1 || points[1] < points[0] || points[1] > upper ||
                    (of_elements && static_cast<std::int64_t>(points[1]) - points[0] >= static_cast<std::int64_t>(zone.faces.size())))
                    throw ParseError(f_.name(), 0,
                                     of_elements ? "a range of face element numbers in " + where
                                                 : "a range of vertex numbers from 1 to " + std::to_string(zone.vertices) + " in " + where,
                                     std::to_string(points[0]) + " to " + std::to_string(points[1]));
                std::vector<cgsize_t> all(static_cast<std::size_t>(points[1] - points[0] + 1));
                std::iota(all.begin(), all.end(), points[0]);
                points = std::move(all);
            }
            if (of_elements) {
                for (cgsize_t e : points) {
                    const std::int64_t f = face_index(zone, order, e);
                    if (f < 0)
                        throw ParseError(f_.name(), 0, "the numbers of face elements (of dimension " + std::to_string(dim_ - 1) +
                                                           ") of " + zone_text(zone) + " in " + where,
                                         std::to_string(e));
                    b.faces.push_back(f);
                }
            } else {
                std::vector<char> in_set(static_cast<std::size_t>(zone.vertices), 0);
                for (cgsize_t v : points) {
                    if (v < 1 || v > zone.vertices)
                        throw ParseError(f_.name(), 0, "vertex numbers from 1 to " + std::to_string(zone.vertices) + " in " + where,
                                         std::to_string(v));
                    in_set[static_cast<std::size_t>(v - 1)] = 1;
                }
                b.faces = faces_on_vertices(zone, in_set);
            }
            zone.boundaries.push_back(std::move(b));
        }
    }

    /// The name of a BC's type; for FamilySpecified, the type of the family
    /// `family`'s first FamilyBC_t (when it has one).
    std::string bc_type_name(CGNS_ENUMT(BCType_t) type, const std::string& family) {
        if (type == CGNS_ENUMV(FamilySpecified) && !family.empty()) {
            int families = 0;
            if (cg_nfamilies(f_.id(), 1, &families) != CG_OK) families = 0;
            for (int fam = 1; fam <= families; ++fam) {
                char name[64] = {};
                int bcs = 0, geos = 0;
                if (cg_family_read(f_.id(), 1, fam, name, &bcs, &geos) != CG_OK || family != name) continue;
                char bc_name[64] = {};
                CGNS_ENUMT(BCType_t) fam_type{};
                if (bcs >= 1 && cg_fambc_read(f_.id(), 1, fam, 1, bc_name, &fam_type) == CG_OK) type = fam_type;
                break;
            }
        }
        const char* text = cg_BCTypeName(type);
        return text ? text : "";
    }

    /// The BC's FamilyName, or `name` when it has none.
    std::string family_or(int z, int bc, const std::string& name) {
        if (cg_goto(f_.id(), 1, "Zone_t", z, "ZoneBC_t", 1, "BC_t", bc, "end") != CG_OK) return name;
        char family[64] = {};
        if (cg_famname_read(family) != CG_OK || !family[0]) return name;
        return family;
    }

    /// The zone's faces whose nodes are all in the set; when it has none, the
    /// faces of its cells that lie on its boundary (one cell) are added first.
    std::vector<std::int64_t> faces_on_vertices(ZoneData& zone, const std::vector<char>& in_set) {
        if (zone.faces.empty()) add_boundary_faces_of_cells(zone);
        std::vector<std::int64_t> taken;
        for (std::size_t f = 0; f < zone.faces.size(); ++f) {
            const auto nodes = zone.faces.nodes_of(f);
            if (std::all_of(nodes.begin(), nodes.end(), [&](NodeId v) { return in_set[static_cast<std::size_t>(v)] != 0; }))
                taken.push_back(static_cast<std::int64_t>(f));
        }
        return taken;
    }

    /// The faces (3D) or edges (2D) of the zone's cells that belong to one cell
    /// only, pointing out of it, in cell order; they are no element of the file
    /// (number 0, section -1).
    void add_boundary_faces_of_cells(ZoneData& zone) {
        const ElementList faces = exterior_faces(dim_, zone.cells);
        for (std::size_t f = 0; f < faces.size(); ++f) {
            zone.faces.push_back(faces.types[f], faces.nodes_of(f));
            zone.face_numbers.push_back(0);
            zone.face_section.push_back(-1);
        }
    }

    void read_joins(int z, ZoneData& zone) {
        int nconns = 0;
        if (cg_nconns(f_.id(), 1, z, &nconns) != CG_OK) return;
        for (int i = 1; i <= nconns; ++i) {
            char name[64] = {}, donor[64] = {};
            CGNS_ENUMT(GridLocation_t) location{};
            CGNS_ENUMT(GridConnectivityType_t) type{};
            CGNS_ENUMT(PointSetType_t) ptset{}, donor_ptset{};
            CGNS_ENUMT(ZoneType_t) donor_type{};
            CGNS_ENUMT(DataType_t) donor_data{};
            cgsize_t npnts = 0, ndonor = 0;
            f_.read_check(cg_conn_info(f_.id(), 1, z, i, name, &location, &type, &ptset, &npnts, donor, &donor_type,
                                       &donor_ptset, &donor_data, &ndonor),
                          "connectivity " + std::to_string(i) + " of " + zone_text(zone));
            // Only vertex-to-vertex 1-to-1 joins say which points are one; other kinds are left alone.
            if (type != CGNS_ENUMV(Abutting1to1) || location != CGNS_ENUMV(Vertex) || ptset != CGNS_ENUMV(PointList) ||
                donor_ptset != CGNS_ENUMV(PointListDonor) || donor_type != CGNS_ENUMV(Unstructured))
                continue;
            const std::string where = "connectivity '" + std::string(name) + "' of " + zone_text(zone);
            if (npnts != ndonor || npnts < 0 || npnts > limit_)
                throw ParseError(f_.name(), 0, "as many donor points as points (" + std::to_string(npnts) + ") in " + where,
                                 std::to_string(ndonor));
            ZoneJoin join{donor, std::vector<cgsize_t>(static_cast<std::size_t>(npnts)),
                          std::vector<cgsize_t>(static_cast<std::size_t>(npnts))};
            if (npnts > 0)
                f_.read_check(cg_conn_read(f_.id(), 1, z, i, join.points.data(), CGNS_ENUMV(Integer), join.donor_points.data()),
                              "the points of " + where);
            for (cgsize_t v : join.points)
                if (v < 1 || v > zone.vertices)
                    throw ParseError(f_.name(), 0, "vertex numbers from 1 to " + std::to_string(zone.vertices) + " in " + where,
                                     std::to_string(v));
            zone.joins.push_back(std::move(join));
        }
    }

    std::filesystem::path path_;
    OpenFile& f_;
    int dim_;
    std::int64_t limit_;
};

/// Union-find over all zones' vertices; each set's root is its first vertex.
struct VertexSets {
    std::vector<std::int64_t> parent;
    std::int64_t root(std::int64_t v) {
        while (parent[static_cast<std::size_t>(v)] != v) {
            parent[static_cast<std::size_t>(v)] = parent[static_cast<std::size_t>(parent[static_cast<std::size_t>(v)])];
            v = parent[static_cast<std::size_t>(v)];
        }
        return v;
    }
    void join(std::int64_t a, std::int64_t b) {
        a = root(a);
        b = root(b);
        if (a != b) parent[static_cast<std::size_t>(std::max(a, b))] = std::min(a, b);
    }
};

/// The families of base 1 with a FamilyBC_t (boundary families): name and BC type name.
std::vector<std::pair<std::string, std::string>> read_boundary_families(const OpenFile& f) {
    std::vector<std::pair<std::string, std::string>> families;
    int count = 0;
    if (cg_nfamilies(f.id(), 1, &count) != CG_OK) return families;
    for (int fam = 1; fam <= count; ++fam) {
        char name[64] = {}, bc_name[64] = {};
        int bcs = 0, geos = 0;
        CGNS_ENUMT(BCType_t) type{};
        if (cg_family_read(f.id(), 1, fam, name, &bcs, &geos) != CG_OK || bcs < 1) continue;
        if (cg_fambc_read(f.id(), 1, fam, 1, bc_name, &type) != CG_OK) continue;
        const char* text = cg_BCTypeName(type);
        families.emplace_back(name, text ? text : "");
    }
    return families;
}

Mesh join_zones(const std::string& file, int dim, std::vector<ZoneData>& zones,
                const std::vector<std::pair<std::string, std::string>>& boundary_families, CgnsSource* source) {
    std::vector<std::int64_t> offset(zones.size() + 1, 0);
    for (std::size_t z = 0; z < zones.size(); ++z) offset[z + 1] = offset[z] + zones[z].vertices;
    if (offset.back() > std::numeric_limits<NodeId>::max())
        throw FormatError(file + ": " + std::to_string(offset.back()) + " points; dgwarp's node ids hold at most " +
                          std::to_string(std::numeric_limits<NodeId>::max()));
    VertexSets sets;
    sets.parent.resize(static_cast<std::size_t>(offset.back()));
    std::iota(sets.parent.begin(), sets.parent.end(), 0);
    for (std::size_t z = 0; z < zones.size(); ++z)
        for (const ZoneJoin& j : zones[z].joins) {
            std::size_t d = 0;
            while (d < zones.size() && zones[d].name != j.donor) ++d;
            if (d == zones.size())
                throw ParseError(file, 0, "a donor zone of base 1 in the connectivity of " + zone_text(zones[z]), j.donor);
            for (std::size_t i = 0; i < j.points.size(); ++i) {
                const cgsize_t v = j.donor_points[i];
                if (v < 1 || v > zones[d].vertices)
                    throw ParseError(file, 0,
                                     "donor vertex numbers from 1 to " + std::to_string(zones[d].vertices) + " (" +
                                         zone_text(zones[d]) + ") in the connectivity of " + zone_text(zones[z]),
                                     std::to_string(v));
                sets.join(offset[z] + j.points[i] - 1, offset[d] + v - 1);
            }
        }

    Mesh mesh;
    mesh.dim = dim;
    std::vector<NodeId> point_of(sets.parent.size());
    for (std::size_t v = 0; v < point_of.size(); ++v) {
        const std::int64_t r = sets.root(static_cast<std::int64_t>(v));
        if (r != static_cast<std::int64_t>(v)) {
            point_of[v] = point_of[static_cast<std::size_t>(r)];
            continue;
        }
        point_of[v] = static_cast<NodeId>(mesh.num_points());
        std::size_t z = 0;
        while (offset[z + 1] <= static_cast<std::int64_t>(v)) ++z;
        const std::size_t local = v - static_cast<std::size_t>(offset[z]);
        for (int a = 0; a < dim; ++a) mesh.points.push_back(zones[z].points[local * static_cast<std::size_t>(dim) + static_cast<std::size_t>(a)]);
    }

    auto global = [&](std::size_t z, std::span<const NodeId> nodes) {
        std::vector<NodeId> g(nodes.size());
        for (std::size_t i = 0; i < nodes.size(); ++i) g[i] = point_of[static_cast<std::size_t>(offset[z] + nodes[i])];
        return g;
    };
    std::map<std::string, std::size_t> marker_index;
    auto marker = [&](const std::string& name) -> Marker& {
        auto [it, added] = marker_index.try_emplace(name, mesh.markers.size());
        if (added) {
            mesh.markers.push_back({name, {}});
            if (source) source->marker_types.emplace_back();
        }
        return mesh.markers[it->second];
    };
    if (source) {
        source->marker_types.clear();
        source->zones.clear();
        source->dim = dim;
    }
    for (std::size_t z = 0; z < zones.size(); ++z) {
        const ZoneData& zone = zones[z];
        for (std::size_t c = 0; c < zone.cells.size(); ++c) mesh.cells.push_back(zone.cells.types[c], global(z, zone.cells.nodes_of(c)));
        std::vector<char> referenced(zone.section_names.size(), 0);
        for (const ZoneBoundary& b : zone.boundaries) {
            Marker& m = marker(b.marker);
            if (source && source->marker_types[marker_index[b.marker]].empty()) source->marker_types[marker_index[b.marker]] = b.type;
            for (std::int64_t f : b.faces) {
                const auto fi = static_cast<std::size_t>(f);
                m.elements.push_back(zone.faces.types[fi], global(z, zone.faces.nodes_of(fi)));
                if (zone.face_section[fi] >= 0) referenced[static_cast<std::size_t>(zone.face_section[fi])] = 1;
            }
        }
        // Face sections no BC refers to: markers of their sections' names.
        for (std::size_t s = 0; s < zone.section_names.size(); ++s) {
            if (referenced[s]) continue;
            Marker* m = nullptr;
            for (std::size_t f = 0; f < zone.faces.size(); ++f) {
                if (zone.face_section[f] != static_cast<int>(s)) continue;
                if (!m) m = &marker(zone.section_names[s]);
                m->elements.push_back(zone.faces.types[f], global(z, zone.faces.nodes_of(f)));
            }
        }
        if (source) {
            CgnsZone sz{zone.name, {}};
            sz.points.assign(point_of.begin() + offset[z], point_of.begin() + offset[z + 1]);
            source->zones.push_back(std::move(sz));
        }
    }
    // Zones with neither BCs nor face sections: their exterior faces are one
    // marker, so that the mesh can be deformed (a motion names it).
    if (mesh.markers.empty() && boundary_families.empty()) {
        marker(exterior_marker_name).elements = exterior_faces(dim, mesh.cells);
        if (mesh.markers.back().elements.empty()) mesh.markers.pop_back();
        else if (source) source->exterior_marker = true;
    }
    // Boundary families (with a FamilyBC_t) that no BC names: markers without
    // elements (dgwarp writes a faceless marker, such as OpenFOAM's axis patch, so).
    for (const auto& [family, type] : boundary_families)
        if (!marker_index.count(family)) {
            marker(family);
            if (source) source->marker_types.back() = type;
        }
    if (source) source->num_points = mesh.num_points();
    return mesh;
}

}  // namespace

Mesh read_cgns(const std::filesystem::path& path, CgnsSource* source) {
    OpenFile f(path, CG_MODE_READ, path.string());
    std::error_code ec;
    const std::uintmax_t file_size = std::filesystem::file_size(path, ec);
    int nbases = 0;
    f.read_check(cg_nbases(f.id(), &nbases), "the bases (CGNSBase_t)");
    if (nbases < 1) throw ParseError(f.name(), 0, "a base (CGNSBase_t)", "none");
    char base[64] = {};
    int cell_dim = 0, phys_dim = 0;
    f.read_check(cg_base_read(f.id(), 1, base, &cell_dim, &phys_dim), "base 1");
    if (cell_dim != 2 && cell_dim != 3)
        throw FormatError(f.name() + ": base '" + base + "' has cell dimension " + std::to_string(cell_dim) +
                          "; dgwarp reads 2D and 3D meshes");
    if (phys_dim < cell_dim || phys_dim > 3)
        throw ParseError(f.name(), 0, "a physical dimension from " + std::to_string(cell_dim) + " to 3 in base '" + base + "'",
                         std::to_string(phys_dim));
    int nzones = 0;
    f.read_check(cg_nzones(f.id(), 1, &nzones), "the zones of base '" + std::string(base) + "'");
    if (nzones < 1) throw ParseError(f.name(), 0, "a zone in base '" + std::string(base) + "'", "none");
    Reader reader(path, f, cell_dim, ec ? 0 : file_size);
    std::vector<ZoneData> zones;
    for (int z = 1; z <= nzones; ++z) zones.push_back(reader.read_zone(z));
    const auto families = read_boundary_families(f);
    f.close();
    Mesh mesh = join_zones(path.string(), cell_dim, zones, families, source);
    if (source) source->file = path;
    try {
        validate(mesh);
    } catch (const MeshError& e) {
        throw MeshError(path.string() + ": " + e.what(), e.marker(), e.index());
    }
    return mesh;
}

}  // namespace dgwarp
