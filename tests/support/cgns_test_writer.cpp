#include "support/cgns_test_writer.hpp"

#include <cgns_io.h>
#include <cgnslib.h>

#include <set>
#include <stdexcept>

namespace dgwarp::test {

static_assert(sizeof(cgsize_t) == sizeof(cgns_size));
static_assert(cgns_code::BAR_2 == CGNS_ENUMV(BAR_2) && cgns_code::TRI_3 == CGNS_ENUMV(TRI_3) &&
              cgns_code::TRI_6 == CGNS_ENUMV(TRI_6) && cgns_code::QUAD_4 == CGNS_ENUMV(QUAD_4) &&
              cgns_code::TETRA_4 == CGNS_ENUMV(TETRA_4) && cgns_code::PYRA_5 == CGNS_ENUMV(PYRA_5) &&
              cgns_code::PENTA_6 == CGNS_ENUMV(PENTA_6) && cgns_code::HEXA_8 == CGNS_ENUMV(HEXA_8) &&
              cgns_code::MIXED == CGNS_ENUMV(MIXED));
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
            if (s.type == cgns_code::MIXED) {  // CGNS 3.4: MIXED with its ElementStartOffset
                std::vector<cgsize_t> offsets{0};
                for (std::size_t at = 0; at < s.connectivity.size();) {
                    int npe = 0;
                    cgns_test_check(cg_npe(static_cast<CGNS_ENUMT(ElementType_t)>(s.connectivity[at]), &npe), "npe");
                    at += 1 + static_cast<std::size_t>(npe);
                    offsets.push_back(static_cast<cgsize_t>(at));
                }
                cgns_test_check(cg_poly_section_write(fn, B, Z, s.name.c_str(), static_cast<CGNS_ENUMT(ElementType_t)>(s.type), start, start + s.count - 1, 0,
                                                      s.connectivity.data(), offsets.data(), &S),
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
    const cgsize_t size = static_cast<cgsize_t>(bytes.size());
    check(cgio_set_dimensions(cgio, node, type.c_str(), 1, &size), "data type " + type);
    check(cgio_write_all_data(cgio, node, bytes.data()), "data");
    check(cgio_close_file(cgio), "close");
}

}  // namespace dgwarp::test
