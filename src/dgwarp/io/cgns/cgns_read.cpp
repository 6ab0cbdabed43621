// Reading CGNS files (cgns.hpp): each zone is read on its own (zone-local
// vertex numbers), then the zones are joined into one mesh.
#include <cgnslib.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>
#include <span>
#include <string>
#include <vector>

#include "dgwarp/core/error.hpp"
#include "dgwarp/io/cgns/cgns.hpp"
#include "dgwarp/io/cgns/cgns_file.hpp"
#include "dgwarp/io/openfoam/openfoam_poly_mesh.hpp"
#include "dgwarp/mesh/polyhedron_faces.hpp"

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
        } else if (t == CellType::polyhedron) {
            const auto [f0, f1] = cells.faces_of(c);
            for (std::int64_t f = f0; f < f1; ++f) {
                const auto ring = cells.face_nodes_of(f);
                all.push_back({polygon_type(ring.size()), {ring.begin(), ring.end()}});
            }
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
    std::vector<char> section_cell_faces;  // per section: an NGON_n section whose faces NFACE_n cells use
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

    /// An element section as the file holds it (1-based numbers, CGNS order).
    struct RawSection {
        std::string where;  // "section 'Cells' of zone 'Zone'"
        int type = 0;
        cgsize_t start = 0;
        std::int64_t count = 0;
        std::int64_t data_size = 0;     // the connectivity's size (ElementDataSize)
        std::vector<cgsize_t> data;     // read when the section is taken, then dropped
        std::vector<cgsize_t> offsets;  // MIXED, NGON_n, NFACE_n (ElementStartOffset): count + 1 values
    };

    /// The faces of the zone's NGON_n sections (zone vertices, 0-based), found
    /// by element number: what NFACE_n elements refer to.
    struct NgonFaces {
        struct Range {
            cgsize_t start = 0;
            std::int64_t count = 0;
            std::size_t section = 0;      // index into the zone's sections
            std::int64_t first_face = 0;  // its first face in `offsets`
        };
        std::vector<Range> ranges;
        std::vector<std::int64_t> offsets{0};  // face k: nodes[offsets[k] .. offsets[k+1])
        std::vector<NodeId> nodes;
        /// The face of element number `number`, and its section; -1 when no NGON_n element has it.
        std::int64_t find(std::int64_t number, std::size_t& section) const {
            for (const Range& r : ranges)
                if (number >= r.start && number - r.start < r.count) {
                    section = r.section;
                    return r.first_face + (number - r.start);
                }
            return -1;
        }
    };

    void read_sections(int z, ZoneData& zone) {
        int nsections = 0;
        f_.read_check(cg_nsections(f_.id(), 1, z, &nsections), "the element sections of " + zone_text(zone));
        std::vector<RawSection> sections;  // headers; each one's connectivity read when it is taken, then dropped
        std::vector<int> parent_flags;
        for (int s = 1; s <= nsections; ++s) {
            parent_flags.push_back(0);
            sections.push_back(read_section_header(z, s, zone, parent_flags.back()));
        }
        zone.section_cell_faces.assign(sections.size(), 0);
        // NGON_n faces first (an NFACE_n section may come before them), checked once.
        NgonFaces ngon;
        for (std::size_t s = 0; s < sections.size(); ++s)
            if (sections[s].type == CGNS_ENUMV(NGON_n)) {
                read_connectivity(z, static_cast<int>(s) + 1, parent_flags[s], sections[s]);
                add_ngon_faces(zone, s, sections[s], ngon);
                drop_connectivity(sections[s]);
            }
        for (std::size_t s = 0; s < sections.size(); ++s) {
            RawSection& r = sections[s];
            if (r.type == CGNS_ENUMV(NGON_n)) {
                take_ngon(zone, s, r, ngon);
                continue;
            }
            read_connectivity(z, static_cast<int>(s) + 1, parent_flags[s], r);
            if (r.type == CGNS_ENUMV(NFACE_n)) take_nface(zone, r, ngon);
            else take_elements(zone, static_cast<int>(s), r.where, r.type, r.start, r.count, r.data, r.offsets);
            drop_connectivity(r);
        }
    }

    /// Section s's header, checked against the file's size and its element
    /// type (its connectivity's size too, not read).
    RawSection read_section_header(int z, int s, ZoneData& zone, int& parent_flag) {
        char name[64] = {};
        CGNS_ENUMT(ElementType_t) type{};
        cgsize_t start = 0, end = 0;
        int nbndry = 0;
        f_.read_check(cg_section_read(f_.id(), 1, z, s, name, &type, &start, &end, &nbndry, &parent_flag),
                      "element section " + std::to_string(s) + " of " + zone_text(zone));
        RawSection r;
        r.where = "section '" + std::string(name) + "' of " + zone_text(zone);
        r.type = type;
        r.start = start;
        zone.section_names.push_back(name);
        const std::string& where = r.where;
        r.count = static_cast<std::int64_t>(end) - start + 1;
        const std::int64_t count = r.count;
        if (start < 1 || count < 1 || count > limit_)
            throw ParseError(f_.name(), 0, "an element range from 1 with 1 to " + std::to_string(limit_) +
                                               " elements in " + where,
                             std::to_string(start) + " to " + std::to_string(end));
        const bool poly = type == CGNS_ENUMV(NGON_n) || type == CGNS_ENUMV(NFACE_n);
        CellType cell{};
        if (type != CGNS_ENUMV(MIXED) && !poly && !cgns::cell_type_of(type, cell))
            throw FormatError(f_.name() + ": " + where + " holds " + cgns::element_type_name(type) +
                              " elements; dgwarp reads linear elements only (NODE, BAR_2, TRI_3, QUAD_4, TETRA_4, "
                              "PYRA_5, PENTA_6, HEXA_8, MIXED sections of them, NGON_n and NFACE_n)");
        if (type == CGNS_ENUMV(NFACE_n) && dim_ == 2)
            throw FormatError(f_.name() + ": " + where + " holds NFACE_n elements in a 2D base; dgwarp reads a 2D "
                              "zone's polygons as NGON_n elements (its cells), not as NFACE_n cells of edges");
        cgsize_t data_size = 0;
        f_.read_check(cg_ElementDataSize(f_.id(), 1, z, s, &data_size), "the connectivity size of " + where);
        const std::int64_t expected = type == CGNS_ENUMV(MIXED) || poly ? -1 : count * nodes_per_cell(cell);
        const std::int64_t most = poly ? limit_ : 9 * count;
        if (data_size < 1 || data_size > most || (expected >= 0 && data_size != expected))
            throw ParseError(f_.name(), 0,
                             expected >= 0 ? std::to_string(expected) + " connectivity values (" + std::to_string(count) +
                                                 " " + cgns::element_type_name(type) + ") in " + where
                             : poly        ? "1 to " + std::to_string(most) + " connectivity values in " + where
                                           : "at most 9 connectivity values an element in " + where,
                             std::to_string(data_size));
        r.data_size = data_size;
        return r;
    }

    static void drop_connectivity(RawSection& r) {
        std::vector<cgsize_t>().swap(r.data);
        std::vector<cgsize_t>().swap(r.offsets);
    }

    /// Reads section s's connectivity into r.data (of its header's size), and
    /// for MIXED, NGON_n and NFACE_n its ElementStartOffset into r.offsets.
    void read_connectivity(int z, int s, int parent_flag, RawSection& r) {
        r.data.resize(static_cast<std::size_t>(r.data_size));
        const bool offsets = r.type == CGNS_ENUMV(MIXED) || r.type == CGNS_ENUMV(NGON_n) || r.type == CGNS_ENUMV(NFACE_n);
        std::vector<cgsize_t> parents(parent_flag ? static_cast<std::size_t>(r.count) * 4 : 0);
        if (offsets) {
            // CGNS 3.4's ElementStartOffset: where each element starts, and the end.
            r.offsets.resize(static_cast<std::size_t>(r.count) + 1);
            f_.read_check(cg_poly_elements_read(f_.id(), 1, z, s, r.data.data(), r.offsets.data(),
                                                parent_flag ? parents.data() : nullptr),
                          "the connectivity of " + r.where);
        } else {
            f_.read_check(cg_elements_read(f_.id(), 1, z, s, r.data.data(), parent_flag ? parents.data() : nullptr),
                          "the connectivity of " + r.where);
        }
    }

    /// Element e of an NGON_n or NFACE_n section: its values data[begin .. end),
    /// checked against the section's ElementStartOffset (from 0, not
    /// decreasing, ending at the connectivity's size) and its least size.
    std::pair<std::size_t, std::size_t> poly_element(const RawSection& r, std::int64_t e, std::int64_t least,
                                                     const char* values) const {
        const auto k = static_cast<std::size_t>(e);
        const std::string element = "element " + std::to_string(r.start + e) + " of " + r.where;
        const std::int64_t begin = r.offsets[k], end = r.offsets[k + 1];
        const auto size = static_cast<std::int64_t>(r.data.size());
        if (e == 0 && begin != 0)
            throw ParseError(f_.name(), 0, "ElementStartOffset 0 for " + element, std::to_string(begin));
        if (end < begin || end > size)
            throw ParseError(f_.name(), 0,
                             "an ElementStartOffset from " + std::to_string(begin) + " to " + std::to_string(size) +
                                 " after " + element,
                             std::to_string(end));
        if (end - begin < least)
            throw ParseError(f_.name(), 0, "at least " + std::to_string(least) + " " + values + " in " + element,
                             std::to_string(end - begin));
        if (e + 1 == r.count && end != size)
            throw ParseError(f_.name(), 0,
                             "the last ElementStartOffset of " + r.where + " to be its connectivity size " +
                                 std::to_string(size),
                             std::to_string(end));
        return {static_cast<std::size_t>(begin), static_cast<std::size_t>(end)};
    }

    /// Checks an NGON_n section (node numbers in range, 3 or more nodes a face
    /// in 3D, 2 or more in 2D) and adds its faces to `ngon`.
    void add_ngon_faces(const ZoneData& zone, std::size_t s, const RawSection& r, NgonFaces& ngon) const {
        ngon.ranges.push_back({r.start, r.count, s, static_cast<std::int64_t>(ngon.offsets.size()) - 1});
        for (std::int64_t e = 0; e < r.count; ++e) {
            const auto [begin, end] = poly_element(r, e, dim_ == 3 ? 3 : 2, "nodes (an NGON_n face)");
            for (std::size_t k = begin; k < end; ++k) {
                const cgsize_t v = r.data[k];
                if (v < 1 || v > zone.vertices)
                    throw ParseError(f_.name(), 0,
                                     "node numbers from 1 to " + std::to_string(zone.vertices) + " in element " +
                                         std::to_string(r.start + e) + " of " + r.where,
                                     std::to_string(v));
                ngon.nodes.push_back(static_cast<NodeId>(v - 1));
            }
            ngon.offsets.push_back(static_cast<std::int64_t>(ngon.nodes.size()));
        }
    }

    /// An NGON_n section's elements: in 3D faces (triangles, quadrilaterals,
    /// polygons) that BCs may name; in 2D cells (polygons of 3 or more nodes)
    /// and edges (2 nodes).
    void take_ngon(ZoneData& zone, std::size_t s, const RawSection& r, const NgonFaces& ngon) const {
        std::int64_t first = 0;
        for (const NgonFaces::Range& range : ngon.ranges)
            if (range.section == s) first = range.first_face;
        for (std::int64_t e = 0; e < r.count; ++e) {
            const auto k = static_cast<std::size_t>(first + e);
            const std::span<const NodeId> ring(ngon.nodes.data() + ngon.offsets[k],
                                               static_cast<std::size_t>(ngon.offsets[k + 1] - ngon.offsets[k]));
            if (dim_ == 2 && ring.size() >= 3) {
                zone.cells.push_back(polygon_type(ring.size()), ring);
            } else {
                zone.faces.push_back(ring.size() == 2 ? CellType::line : polygon_type(ring.size()), ring);
                zone.face_numbers.push_back(r.start + static_cast<cgsize_t>(e));
                zone.face_section.push_back(static_cast<int>(s));
            }
        }
    }

    /// An NFACE_n section's elements (3D): polyhedra of the NGON_n faces they
    /// name. CGNS SIDS 7.3 (Elements_t, https://cgns.github.io/CGNS_docs_current/sids/gridflow.html#Elements):
    /// "The sign of the face number determines its orientation (i.e., the
    /// direction of the face normal, constructed as defined by the convention
    /// for 2-D elements). If the face number is positive, the face normal is
    /// directed outward; if it's negative, the face normal is directed
    /// inward." The 2-D convention (SIDS 3.3.2, conv.html#unst_2d): the
    /// normal is (N2 - N1) x (N3 - N1), the right-hand rule. dgwarp's
    /// polyhedra keep their faces pointing out (mesh.hpp): a face named by a
    /// negative number is reversed. When the signs do not make the faces
    /// agree (each edge run once each way: some writers sign every face
    /// positive), the faces are turned by their shape (orient_polyhedron_faces);
    /// faces that do not close a polyhedron are an error. A cell whose faces
    /// are those of a tetrahedron, pyramid, prism or hexahedron stays a polyhedron.
    void take_nface(ZoneData& zone, const RawSection& r, const NgonFaces& ngon) const {
        std::vector<NodeId> rings;
        std::vector<int> sizes;
        for (std::int64_t e = 0; e < r.count; ++e) {
            const std::string element = "element " + std::to_string(r.start + e) + " of " + r.where;
            const auto [begin, end] = poly_element(r, e, 4, "faces (an NFACE_n cell)");
            rings.clear();
            sizes.clear();
            for (std::size_t k = begin; k < end; ++k) {
                const std::int64_t number = r.data[k];
                std::size_t section = 0;
                const std::int64_t face = number == 0 ? -1 : ngon.find(number < 0 ? -number : number, section);
                if (face < 0)
                    throw ParseError(f_.name(), 0,
                                     "signed numbers of the zone's NGON_n elements in " + element,
                                     std::to_string(number));
                zone.section_cell_faces[section] = 1;
                const auto f = static_cast<std::size_t>(face);
                const auto first = static_cast<std::size_t>(ngon.offsets[f]);
                const auto size = static_cast<std::size_t>(ngon.offsets[f + 1]) - first;
                const std::size_t at = rings.size();
                rings.insert(rings.end(), ngon.nodes.begin() + static_cast<std::ptrdiff_t>(first),
                             ngon.nodes.begin() + static_cast<std::ptrdiff_t>(first + size));
                if (number < 0)  // the face turned round, from the same first node
                    std::reverse(rings.begin() + static_cast<std::ptrdiff_t>(at) + 1, rings.end());
                sizes.push_back(static_cast<int>(size));
            }
            if (!faces_agree(rings, sizes))
                if (const auto why = orient_polyhedron_faces(rings, sizes, zone.points))
                    throw ParseError(f_.name(), 0, "faces that close a polyhedron in " + element, *why);
            // A cell whose faces make a tetrahedron, pyramid, prism or hexahedron is
            // one (as OpenFOAM's are read); any other a polyhedron in a form that
            // depends only on its faces: what write_cgns writes reads back the same.
            foam::push_cell_from_faces(rings, sizes, zone.cells);
        }
    }

    /// Whether every edge of the faces (rings one after another) is run by
    /// exactly two of them, once each way: the faces of a closed polyhedron,
    /// all turned out of it or all into it.
    static bool faces_agree(std::span<const NodeId> rings, std::span<const int> sizes) {
        std::vector<std::pair<NodeId, NodeId>> edges;
        std::size_t at = 0;
        for (int size : sizes) {
            for (int i = 0; i < size; ++i)
                edges.push_back({rings[at + static_cast<std::size_t>(i)], rings[at + static_cast<std::size_t>((i + 1) % size)]});
            at += static_cast<std::size_t>(size);
        }
        std::vector<std::pair<NodeId, NodeId>> sorted = edges;
        std::sort(sorted.begin(), sorted.end());
        if (std::adjacent_find(sorted.begin(), sorted.end()) != sorted.end()) return false;  // an edge run twice one way
        for (const auto& [a, b] : edges)
            if (a == b || !std::binary_search(sorted.begin(), sorted.end(), std::pair<NodeId, NodeId>{b, a})) return false;
        return true;
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
            if (etype == CGNS_ENUMV(NGON_n) || etype == CGNS_ENUMV(NFACE_n))
                throw FormatError(f_.name() + ": " + element + " is " + cgns::element_type_name(etype) +
                                  "; CGNS keeps NGON_n and NFACE_n elements in sections of their own, not in MIXED ones");
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

    /// Whether face f is a boundary element for vertex BCs: not one of the
    /// NGON_n faces of NFACE_n cells (inner faces among them).
    static bool boundary_candidate(const ZoneData& zone, std::size_t f) {
        const int s = zone.face_section[f];
        return s < 0 || !zone.section_cell_faces[static_cast<std::size_t>(s)];
    }

    /// The zone's faces whose nodes are all in the set; when it has none (the
    /// NGON_n faces of NFACE_n cells are no such face), the faces of its cells
    /// that lie on its boundary (one cell) are added first.
    std::vector<std::int64_t> faces_on_vertices(ZoneData& zone, const std::vector<char>& in_set) {
        bool any = false;
        for (std::size_t f = 0; f < zone.faces.size() && !any; ++f) any = boundary_candidate(zone, f);
        if (!any) add_boundary_faces_of_cells(zone);
        std::vector<std::int64_t> taken;
        for (std::size_t f = 0; f < zone.faces.size(); ++f) {
            if (!boundary_candidate(zone, f)) continue;
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
        for (std::size_t c = 0; c < zone.cells.size(); ++c) {
            if (zone.cells.types[c] != CellType::polyhedron) {
                mesh.cells.push_back(zone.cells.types[c], global(z, zone.cells.nodes_of(c)));
                continue;
            }
            std::vector<NodeId> rings;
            std::vector<int> sizes;
            const auto [f0, f1] = zone.cells.faces_of(c);
            for (std::int64_t f = f0; f < f1; ++f) {
                const std::vector<NodeId> ring = global(z, zone.cells.face_nodes_of(f));
                rings.insert(rings.end(), ring.begin(), ring.end());
                sizes.push_back(static_cast<int>(ring.size()));
            }
            mesh.cells.push_polyhedron(rings, sizes);
        }
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
        // Face sections no BC refers to: markers of their sections' names
        // (not the NGON_n faces of NFACE_n cells: inner faces too).
        for (std::size_t s = 0; s < zone.section_names.size(); ++s) {
            if (referenced[s] || zone.section_cell_faces[s]) continue;
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
