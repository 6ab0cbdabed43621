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
                     MIXED = 20;
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

/// A section of a test zone: element type (MIXED: type codes in the data) and connectivity (1-based).
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

/// Writes base "Base" of cell dimension `dim` (physical dimension 3 when the
/// zones have z, else 2) with `zones`, all unstructured. Throws
/// std::runtime_error with libcgns's message when libcgns refuses.
void write_test_cgns(const std::filesystem::path& path, int dim, const std::vector<TestZone>& zones);

/// Rewrites the node at `node_path` ("/Base/Zone/ZoneBC/wall/GridLocation")
/// of the file as `bytes` of data type `type` (one dimension), through cgio:
/// the damaged content no CGNS writer makes. Throws std::runtime_error when cgio refuses.
void set_cgns_node_data(const std::filesystem::path& path, const std::string& node_path, const std::string& type,
                        const std::string& bytes);

}  // namespace dgwarp::test
