#pragma once
// Shared by the CGNS tests: the committed files (tests/data/cgns) and a small
// writer, on libcgns's mid-level API (cgns_test_writer.cpp), for the files no
// CGNS tool makes (several zones, vertex BCs, families, MIXED sections,
// damaged content). What it writes is checked with cgnscheck when installed
// (CgnsRead.TheTestWriterFilesPassCgnscheck). cgnslib.h is not included here:
// its enumerators (ElementList, Vertex, ...) would clash with dgwarp's names
// in the tests' unity batches; the codes below are CGNS's (checked against
// cgnslib.h in the .cpp).
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "support/test_paths.hpp"

namespace dgwarp::test {

inline std::filesystem::path cgns_data(const std::string& name) { return source_dir() / "tests" / "data" / "cgns" / name; }

/// libcgns's cgsize_t (a 32-bit build).
using cgns_size = std::int32_t;

/// CGNS's ElementType_t and GridLocation_t codes the tests use.
namespace cgns_code {
inline constexpr int BAR_2 = 3, TRI_3 = 5, TRI_6 = 6, QUAD_4 = 7, TETRA_4 = 10, PYRA_5 = 12, PENTA_6 = 14, HEXA_8 = 17,
                     MIXED = 20, NGON_n = 22, NFACE_n = 23;
inline constexpr int Vertex = 2, CellCenter = 3, FaceCenter = 4, EdgeCenter = 8;
inline constexpr int BCSymmetryPlane = 16, BCWall = 20;  // BCType_t
}  // namespace cgns_code

/// A BC of a test zone: PointList (or PointRange when `range`) at `location`.
struct TestBc {
    std::string name;
    std::string family;  // "" for none
    int location = cgns_code::Vertex;
    bool range = false;
    std::vector<cgns_size> points;  // 1-based vertex or element numbers (a range: first, last)
    int type = cgns_code::BCWall;  // the BC's type when it has no family (else FamilySpecified)
    int family_type = 0;           // its family's FamilyBC_t type (written with the family's first BC); 0: none
};

/// A section of a test zone: element type and connectivity (1-based). MIXED:
/// each element's type code before its nodes; NGON_n and NFACE_n: each
/// element's size (its nodes, its faces) before them, as CGNS before 3.4
/// stored them (the writer turns the sizes into the ElementStartOffset).
struct TestSection {
    std::string name;
    int type = cgns_code::TETRA_4;
    cgns_size count = 0;
    std::vector<cgns_size> connectivity;
};

/// A vertex 1-to-1 connectivity to zone `donor`.
struct TestJoin {
    std::string donor;
    std::vector<cgns_size> points, donor_points;
};

struct TestZone {
    std::string name = "Zone";
    std::vector<double> x, y, z;
    std::vector<TestSection> sections;  // numbered one after the other from 1
    cgns_size cells = 0;                // the zone's cell count; 0: the first section's element count
    std::vector<TestBc> bcs;
    std::vector<TestJoin> joins;
};

/// A unit cube cut by the plane x = y into two prisms, as CGNS polyhedra:
/// nine NGON_n faces "Faces" (their normals, by the right-hand rule, noted in
/// the .cpp), two NFACE_n cells "Cells" (A: x >= y, B: y >= x), the faces
/// named negative where their normal points into the cell. `cells_first`:
/// the NFACE_n section before the NGON_n one (the cells are elements 1 and
/// 2, the faces 3 to 11); else the faces are 1 to 9, the cells 10 and 11.
TestZone split_cube_test_zone(bool cells_first);

/// A pyramid (base 1-2-3-4 in z = 0, apex 5 above it) as one NFACE_n cell
/// of five NGON_n faces, the k-th face's number signed by signs[k]. Faces 1,
/// 3 and 5 are written turned into the cell, 2 and 4 out of it: the signs
/// {-1, 1, -1, 1, -1} are right.
TestZone pyramid_test_zone(const std::vector<int>& signs);

/// Writes base "Base" of cell dimension `dim` (physical dimension 3 when the
/// zones have z, else 2) with `zones`, all unstructured. Throws
/// std::runtime_error with libcgns's message when libcgns refuses.
void write_test_cgns(const std::filesystem::path& path, int dim, const std::vector<TestZone>& zones);

/// A section as read back (read_test_cgns): its first element number and
/// its ElementStartOffset (MIXED, NGON_n, NFACE_n) beside TestSection's
/// fields (the connectivity as the file holds it, without sizes).
struct ReadSection {
    TestSection section;
    cgns_size start = 0;
    std::vector<cgns_size> offsets;
};

/// A BC as read back: its name, point set type name ("PointList"), location code and points.
struct ReadBc {
    std::string name;
    std::string point_set;
    int location = 0;
    std::vector<cgns_size> points;
};

/// The sections and BCs of zone 1 of base 1, as libcgns reads them (to check
/// what dgwarp wrote by hand). Throws std::runtime_error when libcgns refuses.
struct ReadZone {
    std::vector<ReadSection> sections;
    std::vector<ReadBc> bcs;
    cgns_size cells = 0;  // the zone's cell count
};
ReadZone read_test_cgns(const std::filesystem::path& path);

/// Rewrites the node at `node_path` ("/Base/Zone/ZoneBC/wall/GridLocation")
/// of the file as `bytes` of data type `type` (one dimension of as many
/// values as the bytes hold: 4 a value for I4 and R4, 8 for I8 and R8), through cgio:
/// the damaged content no CGNS writer makes. Throws std::runtime_error when cgio refuses.
void set_cgns_node_data(const std::filesystem::path& path, const std::string& node_path, const std::string& type,
                        const std::string& bytes);

}  // namespace dgwarp::test
