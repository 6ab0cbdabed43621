// Damaged CGNS files: every prefix of a valid file (HDF5 and ADF) is refused
// with a dgwarp::Error naming the file, never a crash, a hang or a wrong mesh;
// so are files with bytes overwritten.
#include <gtest/gtest.h>

#include <fstream>
#include <random>

#include "dgwarp/core/error.hpp"
#include "dgwarp/io/cgns/cgns.hpp"
#include "io/cgns/cgns_test_support.hpp"
#include "support/cgns_test_writer.hpp"

using namespace dgwarp;
using namespace dgwarp::test;

namespace {

void cgns_write_bytes(const std::filesystem::path& file, const std::string& bytes) {
    std::ofstream out(file, std::ios::binary | std::ios::trunc);
    out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
    ASSERT_TRUE(out.good()) << file;
}

}  // namespace

TEST(CgnsReadDamage, EveryPrefixOfAValidFileFailsCleanly) {
    const auto dir = scratch_dir();
    write_test_cgns(dir / "polyhedra.cgns", 3, {split_cube_test_zone(false)});  // NGON_n and NFACE_n sections
    for (const auto& source : {cgns_data("tet.cgns"), cgns_data("tet-adf.cgns"), dir / "polyhedra.cgns"}) {
        const std::string name = source.filename().string();
        const std::string bytes = slurp(source);
        const Mesh whole = read_cgns(source);
        const auto file = dir / ("cut-" + name);
        // The file grows by one byte a step (truncating a file is slow on some file systems).
        std::ofstream grow(file, std::ios::binary | std::ios::trunc);
        for (std::size_t n = 0; n < bytes.size(); grow.put(bytes[n]), grow.flush(), ++n) {
            ASSERT_TRUE(grow.good());
            try {
                const Mesh mesh = read_cgns(file);
                ASSERT_TRUE(mesh == whole) << name << " cut at " << n << " read as another mesh";
                // HDF5 reads a file whose unused tail was cut; the mesh is then whole.
            } catch (const Error& e) {
                ASSERT_NE(std::string(e.what()).find(file.string()), std::string::npos) << e.what();
            } catch (const std::exception& e) {
                FAIL() << name << " cut at " << n << ": not a dgwarp::Error: " << e.what();
            }
        }
    }
}

// Bytes overwritten at random places: an error or a mesh that passes
// validate() (read_cgns checks it), never a crash.
TEST(CgnsReadDamage, OverwrittenBytesFailCleanly) {
    const auto dir = scratch_dir();
    std::mt19937 random(15);
    write_test_cgns(dir / "polyhedra.cgns", 3, {split_cube_test_zone(false)});  // NGON_n and NFACE_n sections
    for (const auto& source : {cgns_data("tet.cgns"), cgns_data("tet-adf.cgns"), dir / "polyhedra.cgns"}) {
        const std::string name = source.filename().string();
        const std::string bytes = slurp(source);
        std::uniform_int_distribution<std::size_t> at(0, bytes.size() - 1);
        std::uniform_int_distribution<int> value(0, 255);
        for (int trial = 0; trial < 300; ++trial) {
            std::string damaged = bytes;
            for (int k = 0; k < 4; ++k) damaged[at(random)] = static_cast<char>(value(random));
            const auto file = dir / ("damaged-" + name);
            cgns_write_bytes(file, damaged);
            try {
                read_cgns(file);
            } catch (const Error&) {
            } catch (const std::exception& e) {
                FAIL() << name << " trial " << trial << ": not a dgwarp::Error: " << e.what();
            }
        }
    }
}

// Damaged NGON_n and NFACE_n sections: an error naming the file, the section
// and the element, never a crash or a cell of faces that do not close.
TEST(CgnsReadDamage, DamagedPolyhedralSectionsAreNamed) {
    const auto dir = scratch_dir();
    const auto file = dir / "poly.cgns";
    const auto write = [&](const TestZone& z, int dim = 3) { write_test_cgns(file, dim, {z}); };
    // 32-bit integers as a node's data (set_cgns_node_data), for what no writer makes.
    const auto ints = [](const std::vector<std::int32_t>& values) {
        return std::string(reinterpret_cast<const char*>(values.data()), values.size() * sizeof(std::int32_t));
    };
    TestZone z = split_cube_test_zone(false);
    ASSERT_NO_THROW(write(z));
    ASSERT_NO_THROW(read_cgns(file));
    // A face number out of range, 0, or naming an element that is no NGON_n face.
    for (const cgns_size bad : {99, 0, -10, 12}) {
        z = split_cube_test_zone(false);
        z.sections[1].connectivity[2] = bad;  // A's second face
        z.sections.push_back({"wall", cgns_code::TRI_3, 1, {1, 2, 3}});  // element 12
        write(z);
        expect_cgns_error<ParseError>(
            file, {file.string(), "signed numbers of the zone's NGON_n elements in element 10 of section 'Cells' of zone 'Zone'",
                   "found '" + std::to_string(bad) + "'"});
    }
    // A face of two nodes; a node out of range.
    z = split_cube_test_zone(false);
    z.sections[0].connectivity[0] = 2;
    z.sections[0].connectivity.erase(z.sections[0].connectivity.begin() + 3);
    write(z);
    expect_cgns_error<ParseError>(
        file, {file.string(), "at least 3 nodes (an NGON_n face) in element 1 of section 'Faces' of zone 'Zone'", "found '2'"});
    z = split_cube_test_zone(false);
    z.sections[0].connectivity[5] = 9;  // face 2: 1, 9, 4
    write(z);
    expect_cgns_error<ParseError>(file, {file.string(), "node numbers from 1 to 8 in element 2 of section 'Faces'", "found '9'"});
    // ElementStartOffset decreasing, or not from 0.
    write(split_cube_test_zone(false));
    set_cgns_node_data(file, "/Base/Zone/Faces/ElementStartOffset", "I4", ints({0, 3, 2, 9, 12, 16, 20, 24, 28, 32}));
    expect_cgns_error<ParseError>(file, {file.string(), "an ElementStartOffset from 3 to 32 after element 2 of section 'Faces'",
                                                "found '2'"});
    write(split_cube_test_zone(false));
    set_cgns_node_data(file, "/Base/Zone/Cells/ElementStartOffset", "I4", ints({1, 5, 10}));
    expect_cgns_error<ParseError>(file, {file.string(), "ElementStartOffset 0 for element 10 of section 'Cells'", "found '1'"});
    // A cell of three faces; a cell whose faces do not close (the cut face left out).
    z = split_cube_test_zone(false);
    z.sections[1].connectivity = {3, -1, 3, 5, 5, -2, 4, 7, 8, 9};
    write(z);
    expect_cgns_error<ParseError>(
        file, {file.string(), "at least 4 faces (an NFACE_n cell) in element 10 of section 'Cells'", "found '3'"});
    z = split_cube_test_zone(false);
    z.sections[1].connectivity = {4, -1, 3, 5, 6, 5, -2, 4, 7, 8, 9};
    write(z);
    expect_cgns_error<ParseError>(file, {file.string(), "faces that close a polyhedron in element 10 of section 'Cells'",
                                                "is in 1 of its faces, not 2"});
    // NFACE_n cells in a 2D base; an NGON_n element in a MIXED section.
    TestZone flat;
    flat.x = {0, 1, 0};
    flat.y = {0, 0, 1};
    flat.sections = {{"Edges", cgns_code::NGON_n, 3, {2, 1, 2, 2, 2, 3, 2, 3, 1}}, {"Cells", cgns_code::NFACE_n, 1, {3, 1, 2, 3}}};
    flat.cells = 1;
    write(flat, 2);
    expect_cgns_error<FormatError>(file, {file.string(), "section 'Cells' of zone 'Zone' holds NFACE_n elements in a 2D base"});
    flat.sections = {{"All", cgns_code::MIXED, 1, {cgns_code::TRI_3, 1, 2, 3}}};
    write(flat, 2);
    ASSERT_NO_THROW(read_cgns(file));
    set_cgns_node_data(file, "/Base/Zone/All/ElementConnectivity", "I4", ints({cgns_code::NGON_n, 1, 2, 3}));
    expect_cgns_error<FormatError>(
        file, {file.string(), "element 1 of section 'All' of zone 'Zone' is NGON_n; CGNS keeps NGON_n and NFACE_n elements in "
                              "sections of their own"});
}
