// read_vtu: what write_vtu writes reads back equal (points bit for bit, cells,
// markers), VTK XML in the forms other programs write (ascii, binary, zlib),
// and damaged files are ParseErrors naming the line (#17 item 10).
#include "dgwarp/io/vtu/vtu.hpp"

#include <gtest/gtest.h>

#include <sstream>

#include "dgwarp/cases/paper_cases.hpp"
#include "dgwarp/core/error.hpp"
#include "dgwarp/io/mesh_io.hpp"
#include "dgwarp/quality/cell_quality.hpp"
#include "support/test_paths.hpp"

using namespace dgwarp;

namespace {

std::string vtu_text_of(const Mesh& mesh, const MeshFields& fields = {}) {
    std::ostringstream out;
    write_vtu(out, mesh, fields);
    return out.str();
}

// A 2D grid of one triangle and one quadrilateral in ASCII, as a person or
// another program writes it (Int32 connectivity, UInt32 header).
const char* ascii_2d = R"(<?xml version="1.0"?>
<VTKFile type="UnstructuredGrid" version="0.1" byte_order="LittleEndian" header_type="UInt32">
  <UnstructuredGrid>
    <Piece NumberOfPoints="5" NumberOfCells="2">
      <Points>
        <DataArray type="Float32" NumberOfComponents="3" format="ascii">
          0 0 0  1 0 0  1 1 0  0 1 0  2 0.5 0
        </DataArray>
      </Points>
      <Cells>
        <DataArray type="Int32" Name="connectivity" format="ascii">0 1 2 3  1 4 2</DataArray>
        <DataArray type="Int32" Name="offsets" format="ascii">4 7</DataArray>
        <DataArray type="UInt8" Name="types" format="ascii">9 5</DataArray>
      </Cells>
    </Piece>
  </UnstructuredGrid>
</VTKFile>
)";

std::string replaced_once(std::string text, const std::string& from, const std::string& to) {
    const auto at = text.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    return at == std::string::npos ? text : text.replace(at, from.size(), to);
}

}  // namespace

TEST(VtuRead, WhatWriteVtuWritesReadsBackEqual) {
    for (const std::string name : {"rect-box", "twisted-bar", "store"}) {
        SCOPED_TRACE(name);
        const Mesh mesh = make_case(name);
        MeshFields fields;
        fields.cell_data.push_back({"quality", 1, std::vector<double>(mesh.cells.size(), 0.5)});
        EXPECT_EQ(read_vtu_text("case.vtu", vtu_text_of(mesh, fields)), mesh);  // points bit for bit, cells, markers
    }
}

TEST(VtuRead, RealSu2MeshesRoundTripThroughVtuExactly) {
    DGWARP_REQUIRE_SHARED_MESHES();
    const auto dir = test::scratch_dir();
    for (const auto& file : test::su2_meshes()) {
        SCOPED_TRACE(file.filename().string());
        const Mesh mesh = read_mesh(file);
        write_mesh(dir / "m.vtu", mesh);
        EXPECT_EQ(read_mesh(dir / "m.vtu"), mesh);
    }
}

TEST(VtuRead, AsciiFromAnotherProgramAndNoMarkers) {
    const Mesh m = read_vtu_text("ascii.vtu", ascii_2d);
    EXPECT_EQ(m.dim, 2);
    EXPECT_EQ(m.points, (std::vector<double>{0, 0, 1, 0, 1, 1, 0, 1, 2, 0.5}));
    ASSERT_EQ(m.cells.size(), 2u);
    EXPECT_EQ(m.cells.types[0], CellType::quadrilateral);
    EXPECT_EQ(m.cells.types[1], CellType::triangle);
    EXPECT_EQ(std::vector<NodeId>(m.cells.nodes.begin(), m.cells.nodes.end()), (std::vector<NodeId>{0, 1, 2, 3, 1, 4, 2}));
    EXPECT_TRUE(m.markers.empty());
}

TEST(VtuRead, DamagedFilesAreParseErrorsNamingTheLine) {
    struct Case {
        const char* what;
        std::string text;
        const char* expected;  // part of the message
    };
    const std::string a = ascii_2d;
    const Case cases[] = {
        {"a node id out of range", replaced_once(a, "0 1 2 3  1 4 2", "0 1 2 3  1 9 2"), "9"},
        {"an unknown cell type", replaced_once(a, "9 5</DataArray>", "9 77</DataArray>"), "77"},
        {"offsets past the connectivity", replaced_once(a, ">4 7<", ">4 8<"), "offset"},
        {"a coordinate that is not a number", replaced_once(a, "2 0.5 0", "2 abc 0"), "abc"},
        {"too few coordinates", replaced_once(a, "2 0.5 0\n", "2 0.5\n"), "Points"},
        {"a truncated file", a.substr(0, a.size() / 2), ""},
    };
    for (const Case& c : cases) {
        try {
            read_vtu_text("bad.vtu", c.text);
            ADD_FAILURE() << "accepted: " << c.what;
        } catch (const ParseError& e) {
            EXPECT_EQ(e.file(), "bad.vtu") << c.what;
            EXPECT_NE(std::string(e.what()).find(c.expected), std::string::npos) << c.what << ": " << e.what();
        } catch (const std::exception& e) {
            ADD_FAILURE() << c.what << ": not a ParseError: " << e.what();
        }
    }
    // Another VTK file type is a FormatError.
    EXPECT_THROW(read_vtu_text("poly.vtu", replaced_once(a, "type=\"UnstructuredGrid\"", "type=\"PolyData\"")), Error);
}

// The forms meshio writes (Debian's python3-meshio): ascii, binary with zlib
// compression (its default) and without; our reader gives the same mesh.
TEST(VtuRead, MeshioWrittenFilesReadTheSame) {
    const auto dir = test::scratch_dir();
    ASSERT_EQ(test::run_command("/usr/bin/python3 -c 'import meshio'").exit_code, 0)
        << "python3-meshio is not installed (scripts/install-deps.sh installs it)";
    const Mesh mesh = make_case("store");
    write_mesh(dir / "ours.vtu", mesh);
    const std::string script =
        "import meshio, sys\n"
        "m = meshio.read(sys.argv[1])\n"
        "meshio.write(sys.argv[2] + '_ascii.vtu', m, binary=False)\n"
        "meshio.write(sys.argv[2] + '_zlib.vtu', m, binary=True, compression='zlib')\n"
        "meshio.write(sys.argv[2] + '_raw.vtu', m, binary=True, compression=None)\n";
    test::write_text(dir / "convert.py", script);
    const test::CommandResult r = test::run_command("/usr/bin/python3 " + test::quoted(dir / "convert.py") + " " +
                                                    test::quoted(dir / "ours.vtu") + " " + test::quoted(dir / "m"));
    ASSERT_EQ(r.exit_code, 0) << r.err;
    for (const char* form : {"ascii", "zlib", "raw"}) {
        SCOPED_TRACE(form);
        const Mesh back = read_mesh(dir / ("m_" + std::string(form) + ".vtu"));
        EXPECT_EQ(back.dim, mesh.dim);
        EXPECT_EQ(back.cells, mesh.cells);
        if (std::string(form) == "ascii") {
            ASSERT_EQ(back.points.size(), mesh.points.size());
            for (std::size_t i = 0; i < mesh.points.size(); ++i) ASSERT_NEAR(back.points[i], mesh.points[i], 1e-9);  // meshio: 11 digits
        } else {
            EXPECT_EQ(back.points, mesh.points);  // binary: bit for bit
        }
    }
}

namespace {

// VTK's own example of a polyhedron (a tetrahedron given as one, from VTK's
// mailing list): its first face turns inward, the others outward.
const char* vtk_polyhedron = R"(<?xml version="1.0"?>
<VTKFile type="UnstructuredGrid" version="0.1" byte_order="LittleEndian">
<UnstructuredGrid>
<Piece NumberOfPoints="4" NumberOfCells="1">
<Points>
<DataArray type="Float64" Name="Points" NumberOfComponents="3" format="ascii">
0 0 0
1 0 0
.5 1 0
.5 .5 1
</DataArray>
</Points>
<Cells>
<DataArray type="Int64" Name="connectivity" format="ascii">0 1 2 3</DataArray>
<DataArray type="Int64" Name="offsets" format="ascii">4</DataArray>
<DataArray type="UInt8" Name="types" format="ascii">42</DataArray>
<DataArray type="Int64" Name="faces" format="ascii">
4 3 0 1 2
3 0 1 3
3 1 2 3
3 0 2 3
</DataArray>
<DataArray type="Int64" Name="faceoffsets" format="ascii">17</DataArray>
</Cells>
</Piece>
</UnstructuredGrid>
</VTKFile>
)";

}  // namespace

TEST(VtuRead, PolyhedraAndPolygonsRoundTripAndForeignFacesAreTurnedOut) {
    // A snappyHexMesh case (polyhedra, boundary pentagons and hexagons) written and read back: equal.
    const Mesh mesh = read_mesh(test::source_dir() / "tests" / "data" / "openfoam" / "snappy-sphere");
    const std::string text = vtu_text_of(mesh);
    EXPECT_NE(text.find("Name=\"faceoffsets\""), std::string::npos);
    EXPECT_NE(text.find("Name=\"dgwarp_marker_offsets\""), std::string::npos);
    EXPECT_EQ(read_vtu_text("snappy.vtu", text), mesh);
    // VTK's example: every face turned out of the cell (as the tetrahedron's quality sees it).
    const Mesh tet = read_vtu_text("vtk.vtu", vtk_polyhedron);
    ASSERT_EQ(tet.cells.types, std::vector<CellType>{CellType::polyhedron});
    EXPECT_EQ(element_orientation(tet.cells, 0, 3, tet.points), 1);
    const std::vector<NodeId> outward{0, 2, 1, 0, 1, 3, 1, 2, 3, 0, 3, 2};
    EXPECT_EQ(tet.cells.face_nodes, outward);
    // A 2D polygon cell (a hexagon) beside a triangle, written and read back.
    Mesh planar;
    planar.dim = 2;
    planar.points = {0, 0, 2, 0, 3, 1, 2, 2, 0, 2, -1, 1, 4, 2};
    planar.cells.push_back(CellType::polygon, std::vector<NodeId>{0, 1, 2, 3, 4, 5});
    planar.cells.push_back(CellType::triangle, std::vector<NodeId>{1, 6, 2});
    EXPECT_EQ(read_vtu_text("planar.vtu", vtu_text_of(planar)), planar);
}

TEST(VtuRead, DamagedPolyhedraAreParseErrors) {
    const auto expect_error = [](const std::string& text, const std::string& part) {
        try {
            read_vtu_text("bad.vtu", text);
            ADD_FAILURE() << "no error for " << part;
        } catch (const ParseError& e) {
            EXPECT_NE(std::string(e.what()).find(part), std::string::npos) << e.what();
        }
    };
    expect_error(replaced_once(vtk_polyhedron, ">17<", ">16<"), "faceoffset");
    expect_error(replaced_once(vtk_polyhedron, "3 0 2 3\n", "3 0 2 9\n"), "node ids from 0 to 3");
    expect_error(replaced_once(vtk_polyhedron, "3 0 2 3\n", "3 0 1 3\n"), "faces that close polyhedron 0");
    expect_error(replaced_once(vtk_polyhedron, "4 3 0 1 2", "3 3 0 1 2"), "polyhedron 0");
    expect_error(replaced_once(vtk_polyhedron, "<DataArray type=\"Int64\" Name=\"faceoffsets\" format=\"ascii\">17</DataArray>", ""),
                 "faceoffsets");
}
