#include "support/cgns_test_writer.hpp"

#include <cgns_io.h>
#include <cgnslib.h>

#include <algorithm>
#include <set>
#include <stdexcept>

namespace dgwarp::test {

static_assert(sizeof(cgsize_t) == sizeof(cgns_size));
static_assert(cgns_code::BAR_2 == CGNS_ENUMV(BAR_2) && cgns_code::TRI_3 == CGNS_ENUMV(TRI_3) &&
              cgns_code::TRI_6 == CGNS_ENUMV(TRI_6) && cgns_code::QUAD_4 == CGNS_ENUMV(QUAD_4) &&
              cgns_code::TETRA_4 == CGNS_ENUMV(TETRA_4) && cgns_code::PYRA_5 == CGNS_ENUMV(PYRA_5) &&
              cgns_code::PENTA_6 == CGNS_ENUMV(PENTA_6) && cgns_code::HEXA_8 == CGNS_ENUMV(HEXA_8) &&
              cgns_code::MIXED == CGNS_ENUMV(MIXED) && cgns_code::NGON_n == CGNS_ENUMV(NGON_n) &&
              cgns_code::NFACE_n == CGNS_ENUMV(NFACE_n));
static_assert(cgns_code::BCSymmetryPlane == CGNS_ENUMV(BCSymmetryPlane) && cgns_code::BCWall == CGNS_ENUMV(BCWall));
static_assert(cgns_code::Vertex == CGNS_ENUMV(Vertex) && cgns_code::CellCenter == CGNS_ENUMV(CellCenter) &&
              cgns_code::FaceCenter == CGNS_ENUMV(FaceCenter) && cgns_code::EdgeCenter == CGNS_ENUMV(EdgeCenter));

namespace {

void cgns_test_check(int status, const std::string& what) {
    if (status != CG_OK) throw std::runtime_error("test CGNS writer: " + what + ": " + cg_get_error());
}

}  // namespace

void write_test_cgns(const std::filesystem::path& path, int dim, const std::vector<TestZone>& zones) {
    int fn = 0, B = 0;
    cgns_test_check(cg_open(path.c_str(), CG_MODE_WRITE, &fn), "open");
    const int phys = zones.front().z.empty() ? 2 : 3;
    cgns_test_check(cg_base_write(fn, "Base", dim, phys, &B), "base");
    std::set<std::string> families;  // the Family_t nodes written
    for (const TestZone& zone : zones) {
        int Z = 0, C = 0;
        const auto n = static_cast<cgsize_t>(zone.x.size());
        const cgsize_t ncells = zone.cells ? zone.cells : zone.sections.front().count;
        cgsize_t size[3] = {n, ncells, 0};
        cgns_test_check(cg_zone_write(fn, B, zone.name.c_str(), size, CGNS_ENUMV(Unstructured), &Z), "zone");
        cgns_test_check(cg_coord_write(fn, B, Z, CGNS_ENUMV(RealDouble), "CoordinateX", zone.x.data(), &C), "x");
        cgns_test_check(cg_coord_write(fn, B, Z, CGNS_ENUMV(RealDouble), "CoordinateY", zone.y.data(), &C), "y");
        if (!zone.z.empty())
            cgns_test_check(cg_coord_write(fn, B, Z, CGNS_ENUMV(RealDouble), "CoordinateZ", zone.z.data(), &C), "z");
        cgsize_t start = 1;
        for (const TestSection& s : zone.sections) {
            int S = 0;
            if (s.type == cgns_code::MIXED || s.type == cgns_code::NGON_n || s.type == cgns_code::NFACE_n) {
                // CGNS 3.4: with its ElementStartOffset
                std::vector<cgsize_t> data, offsets{0};
                const bool sized = s.type != cgns_code::MIXED;
                for (std::size_t at = 0; at < s.connectivity.size();) {
                    int n = 0;
                    if (sized) n = s.connectivity[at++];
                    else cgns_test_check(cg_npe(static_cast<CGNS_ENUMT(ElementType_t)>(s.connectivity[at]), &n), "npe");
                    const std::size_t size = static_cast<std::size_t>(n) + (sized ? 0 : 1);
                    data.insert(data.end(), s.connectivity.begin() + static_cast<std::ptrdiff_t>(at),
                                s.connectivity.begin() + static_cast<std::ptrdiff_t>(std::min(at + size, s.connectivity.size())));
                    at += size;
                    offsets.push_back(static_cast<cgsize_t>(data.size()));
                }
                cgns_test_check(cg_poly_section_write(fn, B, Z, s.name.c_str(), static_cast<CGNS_ENUMT(ElementType_t)>(s.type), start, start + s.count - 1, 0,
                                                      data.data(), offsets.data(), &S),
                                "section " + s.name);
            } else {
                cgns_test_check(cg_section_write(fn, B, Z, s.name.c_str(), static_cast<CGNS_ENUMT(ElementType_t)>(s.type), start, start + s.count - 1, 0,
                                                 s.connectivity.data(), &S),
                                "section " + s.name);
            }
            start += s.count;
        }
        for (const TestBc& bc : zone.bcs) {
            int BC = 0;
            cgns_test_check(cg_boco_write(fn, B, Z, bc.name.c_str(), bc.family.empty() ? static_cast<CGNS_ENUMT(BCType_t)>(bc.type) : CGNS_ENUMV(FamilySpecified),
                                          bc.range ? CGNS_ENUMV(PointRange) : CGNS_ENUMV(PointList),
                                          static_cast<cgsize_t>(bc.points.size()), bc.points.data(), &BC),
                            "BC " + bc.name);
            cgns_test_check(cg_boco_gridlocation_write(fn, B, Z, BC, static_cast<CGNS_ENUMT(GridLocation_t)>(bc.location)), "BC location");
            if (!bc.family.empty()) {
                int F = 0;
                if (families.insert(bc.family).second) {
                    cgns_test_check(cg_family_write(fn, B, bc.family.c_str(), &F), "family");
                    int FB = 0;
                    if (bc.family_type != 0)
                        cgns_test_check(cg_fambc_write(fn, B, F, "FamBC", static_cast<CGNS_ENUMT(BCType_t)>(bc.family_type), &FB),
                                        "family BC");
                }
                cgns_test_check(cg_goto(fn, B, "Zone_t", Z, "ZoneBC_t", 1, "BC_t", BC, "end"), "goto BC");
                cgns_test_check(cg_famname_write(bc.family.c_str()), "family name");
            }
        }
        for (const TestJoin& j : zone.joins) {
            int I = 0;
            cgns_test_check(cg_conn_write(fn, B, Z, ("to " + j.donor).c_str(), CGNS_ENUMV(Vertex), CGNS_ENUMV(Abutting1to1),
                                          CGNS_ENUMV(PointList), static_cast<cgsize_t>(j.points.size()), j.points.data(),
                                          j.donor.c_str(), CGNS_ENUMV(Unstructured), CGNS_ENUMV(PointListDonor),
                                          CGNS_ENUMV(Integer), static_cast<cgsize_t>(j.donor_points.size()),
                                          j.donor_points.data(), &I),
                            "connectivity");
        }
    }
    cgns_test_check(cg_close(fn), "close");
}

TestZone split_cube_test_zone(bool cells_first) {
    TestZone z;
    z.x = {0, 1, 1, 0, 0, 1, 1, 0};
    z.y = {0, 0, 1, 1, 0, 0, 1, 1};
    z.z = {0, 0, 0, 0, 1, 1, 1, 1};
    const TestSection faces{"Faces", cgns_code::NGON_n, 9,
                            {3, 1, 2, 3,     // 1: z = 0 under A, normal +z (into A)
                             3, 1, 3, 4,     // 2: z = 0 under B, +z (into B)
                             3, 5, 6, 7,     // 3: z = 1 over A, +z (out of A)
                             3, 5, 7, 8,     // 4: z = 1 over B, +z (out of B)
                             4, 1, 2, 6, 5,  // 5: y = 0, -y (out of A)
                             4, 2, 3, 7, 6,  // 6: x = 1, +x (out of A)
                             4, 3, 4, 8, 7,  // 7: y = 1, +y (out of B)
                             4, 4, 1, 5, 8,  // 8: x = 0, -x (out of B)
                             4, 1, 3, 7, 5}};  // 9: x = y, (1, -1, 0) (into A, out of B)
    const cgns_size f = cells_first ? 2 : 0;  // face k is element f + k
    const TestSection cells{"Cells", cgns_code::NFACE_n, 2,
                            {5, -(f + 1), f + 3, f + 5, f + 6, -(f + 9),  // A
                             5, -(f + 2), f + 4, f + 7, f + 8, f + 9}};   // B
    z.sections = cells_first ? std::vector<TestSection>{cells, faces} : std::vector<TestSection>{faces, cells};
    z.cells = 2;
    return z;
}

TestZone pyramid_test_zone(const std::vector<int>& signs) {
    TestZone z;
    z.x = {0, 1, 1, 0, 0.5};
    z.y = {0, 0, 1, 1, 0.5};
    z.z = {0, 0, 0, 0, 1};
    z.sections = {{"Faces", cgns_code::NGON_n, 5,
                   {4, 1, 2, 3, 4,  // +z: into the pyramid
                    3, 1, 2, 5,     // out (-y side)
                    3, 2, 5, 3,     // into (+x side)
                    3, 3, 4, 5,     // out (+y side)
                    3, 4, 5, 1}},   // into (-x side)
                  {"Cells", cgns_code::NFACE_n, 1, {static_cast<cgns_size>(signs.size())}}};
    for (std::size_t k = 0; k < signs.size(); ++k) z.sections[1].connectivity.push_back(signs[k] * static_cast<cgns_size>(k + 1));
    z.cells = 1;
    return z;
}

ReadZone read_test_cgns(const std::filesystem::path& path) {
    int fn = 0;
    cgns_test_check(cg_open(path.c_str(), CG_MODE_READ, &fn), "open " + path.string());
    ReadZone zone;
    char name[64] = {};
    cgsize_t size[9] = {};
    cgns_test_check(cg_zone_read(fn, 1, 1, name, size), "zone");
    zone.cells = size[1];
    int nsections = 0;
    cgns_test_check(cg_nsections(fn, 1, 1, &nsections), "sections");
    for (int s = 1; s <= nsections; ++s) {
        ReadSection r;
        CGNS_ENUMT(ElementType_t) type{};
        cgsize_t start = 0, end = 0, data_size = 0;
        int nbndry = 0, parent_flag = 0;
        cgns_test_check(cg_section_read(fn, 1, 1, s, name, &type, &start, &end, &nbndry, &parent_flag), "section");
        r.section.name = name;
        r.section.type = type;
        r.section.count = end - start + 1;
        r.start = start;
        cgns_test_check(cg_ElementDataSize(fn, 1, 1, s, &data_size), "data size");
        r.section.connectivity.resize(static_cast<std::size_t>(data_size));
        if (type == CGNS_ENUMV(MIXED) || type == CGNS_ENUMV(NGON_n) || type == CGNS_ENUMV(NFACE_n)) {
            r.offsets.resize(static_cast<std::size_t>(r.section.count) + 1);
            cgns_test_check(cg_poly_elements_read(fn, 1, 1, s, r.section.connectivity.data(), r.offsets.data(), nullptr),
                            "poly elements");
        } else {
            cgns_test_check(cg_elements_read(fn, 1, 1, s, r.section.connectivity.data(), nullptr), "elements");
        }
        zone.sections.push_back(std::move(r));
    }
    int nbocos = 0;
    cgns_test_check(cg_nbocos(fn, 1, 1, &nbocos), "BCs");
    for (int bc = 1; bc <= nbocos; ++bc) {
        ReadBc b;
        CGNS_ENUMT(BCType_t) bctype{};
        CGNS_ENUMT(PointSetType_t) ptset{};
        CGNS_ENUMT(GridLocation_t) location{};
        CGNS_ENUMT(DataType_t) normal_type{};
        cgsize_t npnts = 0, normal_size = 0;
        int normal_index = 0, ndataset = 0;
        cgns_test_check(cg_boco_info(fn, 1, 1, bc, name, &bctype, &ptset, &npnts, &normal_index, &normal_size, &normal_type,
                                     &ndataset),
                        "BC");
        cgns_test_check(cg_boco_gridlocation_read(fn, 1, 1, bc, &location), "BC location");
        b.name = name;
        b.point_set = cg_PointSetTypeName(ptset);
        b.location = location;
        b.points.resize(static_cast<std::size_t>(npnts));
        cgns_test_check(cg_boco_read(fn, 1, 1, bc, b.points.data(), nullptr), "BC points");
        zone.bcs.push_back(std::move(b));
    }
    cgns_test_check(cg_close(fn), "close");
    return zone;
}

void set_cgns_node_data(const std::filesystem::path& path, const std::string& node_path, const std::string& type,
                        const std::string& bytes) {
    int cgio = 0;
    double root = 0, node = 0;
    const auto check = [&](int status, const std::string& what) {
        if (status == CG_OK) return;
        char message[CGIO_MAX_ERROR_LENGTH + 1] = {};
        cgio_error_message(message);
        if (cgio > 0) cgio_close_file(cgio);
        throw std::runtime_error("test CGNS writer: " + what + ": " + message);
    };
    check(cgio_open_file(path.c_str(), CGIO_MODE_MODIFY, CGIO_FILE_NONE, &cgio), "open " + path.string());
    check(cgio_get_root_id(cgio, &root), "root");
    check(cgio_get_node_id(cgio, root, node_path.c_str(), &node), node_path);
    // The node's dimension counts values: bytes / the type's width (I4 and R4: 4, I8 and R8: 8, else 1).
    const std::size_t width = type == "I4" || type == "R4" ? 4 : type == "I8" || type == "R8" ? 8 : 1;
    if (bytes.size() % width != 0) throw std::runtime_error("test CGNS writer: " + std::to_string(bytes.size()) + " bytes of " + type);
    const cgsize_t size = static_cast<cgsize_t>(bytes.size() / width);
    check(cgio_set_dimensions(cgio, node, type.c_str(), 1, &size), "data type " + type);
    check(cgio_write_all_data(cgio, node, bytes.data()), "data");
    check(cgio_close_file(cgio), "close");
}

}  // namespace dgwarp::test
