// Writing CGNS files: whole meshes read back equal and pass the CGNS
// project's checker; new coordinates written back into a copy of a file keep
// everything else in it.
#include <gtest/gtest.h>

#include <sys/stat.h>

#include "dgwarp/cases/rect_box.hpp"
#include "dgwarp/core/error.hpp"
#include "dgwarp/io/cgns.hpp"
#include "dgwarp/io/gmsh.hpp"
#include "dgwarp/io/openfoam.hpp"
#include "support/cgns_test_writer.hpp"

using namespace dgwarp;
using namespace dgwarp::test;

namespace {

bool cgns_tool_installed(const std::string& tool) { return run_command("command -v " + tool).exit_code == 0; }

/// Meshes of every cell and marker element type: 3D of the four cell types
/// (MIXED cells, markers of triangles and quadrilaterals), one hexahedral
/// case, a 2D box of triangles, one of quadrilaterals.
std::vector<std::pair<std::string, Mesh>> cgns_write_meshes() {
    std::vector<std::pair<std::string, Mesh>> meshes;
    meshes.push_back({"mixed.msh", read_gmsh(cgns_data("sources/mixed.msh"))});
    meshes.push_back({"cavity", read_openfoam(source_dir() / "tests/data/openfoam/cavity")});
    meshes.push_back({"rect-box", make_rect_box()});
    Mesh quads;
    quads.dim = 2;
    quads.points = {0, 0, 1, 0, 2, 0, 0, 1, 1, 1, 2, 1};
    const NodeId q0[] = {0, 1, 4, 3}, q1[] = {1, 2, 5, 4};
    quads.cells.push_back(CellType::quadrilateral, q0);
    quads.cells.push_back(CellType::quadrilateral, q1);
    const NodeId lower0[] = {0, 1}, lower1[] = {1, 2}, right[] = {2, 5};
    quads.markers = {{"lower", {}}, {"right", {}}};
    quads.markers[0].elements.push_back(CellType::line, lower0);
    quads.markers[0].elements.push_back(CellType::line, lower1);
    quads.markers[1].elements.push_back(CellType::line, right);
    meshes.push_back({"quads", quads});
    return meshes;
}

}  // namespace

TEST(CgnsWrite, MeshesReadBackEqual) {
    const auto dir = scratch_dir();
    for (const auto& [name, mesh] : cgns_write_meshes()) {
        const auto file = dir / (name + ".cgns");
        write_cgns(file, mesh);
        EXPECT_TRUE(read_cgns(file) == mesh) << name;
    }
}

TEST(CgnsWrite, CgnscheckAcceptsWhatItWritesAndCgnsToVtkReadsIt) {
    if (!cgns_tool_installed("cgnscheck") || !cgns_tool_installed("cgns_to_vtk"))
        GTEST_SKIP() << "cgnscheck or cgns_to_vtk not installed (Debian package cgns-convert)";
    const auto dir = scratch_dir();
    for (const auto& [name, mesh] : cgns_write_meshes()) {
        const auto file = dir / (name + ".cgns");
        write_cgns(file, mesh);
        CommandResult r = run_command("cgnscheck -w3 " + quoted(file));
        EXPECT_EQ(r.exit_code, 0) << name << r.out << r.err;
        EXPECT_EQ(r.out.find("ERROR"), std::string::npos) << name << "\n" << r.out;
        EXPECT_NE(r.out.find("checking complete"), std::string::npos) << name << "\n" << r.out;
        if (mesh.dim == 2) continue;  // cgns_to_vtk reads 3D bases only
        const auto vtk = dir / (name + "-vtk");
        std::filesystem::create_directories(vtk);
        r = run_command("cgns_to_vtk -a " + quoted(file) + " " + quoted(vtk));
        ASSERT_EQ(r.exit_code, 0) << name << r.out << r.err;
        const std::string grid = slurp(vtk / "Zone.vtk");
        EXPECT_NE(grid.find("POINTS " + std::to_string(mesh.num_points()) + " "), std::string::npos) << name;
        EXPECT_NE(grid.find("CELLS " + std::to_string(mesh.cells.size()) + " "), std::string::npos) << name;
    }
}

TEST(CgnsWrite, MeshesCgnsCannotHoldAreRefusedBeforeWriting) {
    const auto dir = scratch_dir();
    Mesh mesh = make_rect_box();
    for (const std::string& bad : {std::string(), std::string("a/b"), std::string(33, 'm'), std::string("Cells"), std::string(" padded"),
                                 std::string("U\t"), std::string("\nwall"), std::string("wall\r"), std::string("\v")}) {
        Mesh renamed = mesh;
        renamed.markers[0].name = bad;
        EXPECT_THROW(write_cgns(dir / "bad.cgns", renamed), MeshError) << "'" << bad << "'";
    }
    Mesh twice = mesh;
    twice.markers.push_back(twice.markers[0]);
    EXPECT_THROW(write_cgns(dir / "bad.cgns", twice), MeshError);
    EXPECT_FALSE(std::filesystem::exists(dir / "bad.cgns"));
    EXPECT_EQ(std::distance(std::filesystem::directory_iterator(dir), std::filesystem::directory_iterator()), 0);
}

// deform's CGNS output: a copy of the input with new coordinates, in the
// precision the file had; every other node the same (cgnsdiff, when installed).
TEST(CgnsWrite, PointsWrittenBackKeepEveryOtherNodeOfTheFile) {
    const auto dir = scratch_dir();
    for (const std::string name : {"mixed.cgns", "mixed-adf.cgns"}) {
        CgnsSource source;
        const Mesh mesh = read_cgns(cgns_data(name), &source);
        Mesh moved = mesh;
        for (std::size_t i = 0; i < moved.points.size(); ++i) moved.points[i] += 1e-3 * static_cast<double>(i % 7) + 0.1;
        const auto out = dir / ("moved-" + name);
        write_cgns_points(out, source, moved.points);
        EXPECT_TRUE(read_cgns(out) == moved) << name;
        EXPECT_TRUE(read_cgns(cgns_data(name)) == mesh) << name;  // the input is untouched
        if (cgns_tool_installed("cgnsdiff")) {
            // -d: compare the data too; only the three coordinates differ.
            const CommandResult r = run_command("cgnsdiff -d " + quoted(cgns_data(name)) + " " + quoted(out));
            std::size_t lines = 0;
            for (std::size_t at = 0; (at = r.out.find('\n', at)) != std::string::npos; ++at) ++lines;
            EXPECT_EQ(lines, 3u) << r.out << r.err;
            for (const char* axis : {"CoordinateX", "CoordinateY", "CoordinateZ"})
                EXPECT_NE(r.out.find(axis), std::string::npos) << r.out;
        }
    }
    // Several zones: a point shared by two zones moves in both.
    TestZone a, b;
    a.name = "A";
    b.name = "B";
    for (TestZone* z : {&a, &b}) {
        z->x = {0, 1, 0, 0};
        z->y = {0, 0, 1, 0};
        z->z = {0, 0, 0, 1};
        z->sections = {{"Cells", cgns_code::TETRA_4, 1, {1, 2, 3, 4}}};
    }
    b.x = {0, 1, 0, 0};
    b.z = {0, 0, 0, -1};
    b.sections[0].connectivity = {1, 3, 2, 4};
    b.joins = {{"A", {1, 2, 3}, {1, 2, 3}}};
    write_test_cgns(dir / "zones.cgns", 3, {a, b});
    CgnsSource source;
    const Mesh zones = read_cgns(dir / "zones.cgns", &source);
    ASSERT_EQ(zones.num_points(), 5u);
    Mesh moved = zones;
    for (double& x : moved.points) x *= 2;
    write_cgns_points(dir / "zones-moved.cgns", source, moved.points);
    EXPECT_TRUE(read_cgns(dir / "zones-moved.cgns") == moved);
    EXPECT_THROW(write_cgns_points(dir / "short.cgns", source, std::span<const double>(moved.points).first(12)), MeshError);
    EXPECT_FALSE(std::filesystem::exists(dir / "short.cgns"));
}

TEST(CgnsWrite, SinglePrecisionCoordinatesStaySinglePrecision) {
    if (!cgns_tool_installed("aflr3_to_cgns")) GTEST_SKIP() << "aflr3_to_cgns not installed (Debian package cgns-convert)";
    const auto dir = scratch_dir();
    const CommandResult made = run_command("aflr3_to_cgns -f -4 " + quoted(cgns_data("sources/tet.ugrid")) + " " +
                                           quoted(dir / "single.cgns"));
    ASSERT_EQ(made.exit_code, 0) << made.out << made.err;
    CgnsSource source;
    const Mesh mesh = read_cgns(dir / "single.cgns", &source);
    Mesh moved = mesh;
    moved.points[0] = 0.1;  // not a float: written as the float nearest to it
    write_cgns_points(dir / "out.cgns", source, moved.points);
    const Mesh back = read_cgns(dir / "out.cgns");
    EXPECT_EQ(back.points[0], static_cast<double>(0.1f));
    EXPECT_EQ(back.cells, mesh.cells);
}

// A marker without elements (OpenFOAM's axis patch of a wedge case) has no
// section or BC (neither may be empty): a boundary family of its name keeps
// it, and reading gives it back, after the markers with elements.
TEST(CgnsWrite, AMarkerWithoutElementsIsABoundaryFamily) {
    const auto dir = scratch_dir();
    Mesh mesh = make_rect_box();
    mesh.markers.insert(mesh.markers.begin(), Marker{"axis", {}});
    write_cgns(dir / "axis.cgns", mesh);
    CgnsSource info;
    const Mesh back = read_cgns(dir / "axis.cgns", &info);
    Mesh expected = mesh;
    std::rotate(expected.markers.begin(), expected.markers.begin() + 1, expected.markers.end());
    EXPECT_TRUE(back == expected);
    EXPECT_EQ(info.marker_types.back(), "UserDefined");  // libcgns's name of BCTypeUserDefined
    if (cgns_tool_installed("cgnscheck")) {
        const CommandResult r = run_command("cgnscheck " + quoted(dir / "axis.cgns"));
        EXPECT_EQ(r.exit_code, 0) << r.out << r.err;
        EXPECT_EQ(r.out.find("ERROR"), std::string::npos) << r.out;
    }
}
