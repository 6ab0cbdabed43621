// Writing CGNS files: whole meshes read back equal and pass the CGNS
// project's checker; new coordinates written back into a copy of a file keep
// everything else in it.
#include <gtest/gtest.h>

#include <sys/stat.h>

#include "dgwarp/cases/rect_box.hpp"
#include "dgwarp/core/error.hpp"
#include "dgwarp/io/cgns/cgns.hpp"
#include "dgwarp/io/gmsh/gmsh.hpp"
#include "dgwarp/io/openfoam/openfoam.hpp"
#include "dgwarp/io/openfoam/openfoam_poly_mesh.hpp"
#include "dgwarp/quality/cell_quality.hpp"
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

/// The unit cube cut by the plane x = y into two prisms as polyhedra (A: x
/// >= y, B: y >= x), their faces pointing out; markers "bottom" (the two
/// triangles in z = 0, pointing out), "sides" (the four quadrilaterals),
/// "top" (the two triangles in z = 1). The mesh of split_cube_test_zone's file.
Mesh cgns_write_split_cube() {
    Mesh mesh;
    mesh.points = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0, 0, 0, 1, 1, 0, 1, 1, 1, 1, 0, 1, 1};
    const std::vector<int> sizes{3, 3, 4, 4, 4};
    mesh.cells.push_polyhedron(std::vector<NodeId>{0, 2, 1, 4, 5, 6, 0, 1, 5, 4, 1, 2, 6, 5, 0, 4, 6, 2}, sizes);
    mesh.cells.push_polyhedron(std::vector<NodeId>{0, 3, 2, 4, 6, 7, 2, 3, 7, 6, 3, 0, 4, 7, 0, 2, 6, 4}, sizes);
    mesh.markers = {{"bottom", {}}, {"sides", {}}, {"top", {}}};
    const NodeId bottom[2][3] = {{0, 2, 1}, {0, 3, 2}}, top[2][3] = {{4, 5, 6}, {4, 6, 7}};
    const NodeId sides[4][4] = {{0, 1, 5, 4}, {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7}};
    for (const auto& t : bottom) mesh.markers[0].elements.push_back(CellType::triangle, t);
    for (const auto& q : sides) mesh.markers[1].elements.push_back(CellType::quadrilateral, q);
    for (const auto& t : top) mesh.markers[2].elements.push_back(CellType::triangle, t);
    return mesh;
}

/// A face ring from its smallest node on, the same way round: the face and its orientation, whatever its first node.
std::vector<NodeId> cgns_write_canonical(std::span<const NodeId> ring) {
    const auto k = static_cast<std::size_t>(std::min_element(ring.begin(), ring.end()) - ring.begin());
    std::vector<NodeId> out;
    for (std::size_t i = 0; i < ring.size(); ++i) out.push_back(ring[(k + i) % ring.size()]);
    return out;
}

/// The faces of cell c (a polyhedron's; a fixed type's outward faces), canonical and sorted.
std::vector<std::vector<NodeId>> cgns_write_cell_faces(const ElementList& cells, std::size_t c) {
    std::vector<std::vector<NodeId>> faces;
    if (cells.types[c] == CellType::polyhedron) {
        const auto [f0, f1] = cells.faces_of(c);
        for (std::int64_t f = f0; f < f1; ++f) faces.push_back(cgns_write_canonical(cells.face_nodes_of(f)));
    } else {
        const auto nodes = cells.nodes_of(c);
        const foam::FaceTable& table = foam::outward_faces(cells.types[c]);
        for (int k = 0; k < table.count; ++k) {
            std::vector<NodeId> ring;
            for (int i = 0; i < table.size[k]; ++i) ring.push_back(nodes[static_cast<std::size_t>(table.node[k][i])]);
            faces.push_back(cgns_write_canonical(ring));
        }
    }
    std::sort(faces.begin(), faces.end());
    return faces;
}

/// The cells as the CGNS reader gives back their NFACE_n faces: from their
/// outward faces (foam::push_cell_from_faces: a tetrahedron, pyramid, prism or
/// hexahedron when the faces make one, else a canonical polyhedron).
ElementList cgns_write_as_read(const ElementList& cells) {
    ElementList out;
    for (std::size_t c = 0; c < cells.size(); ++c) {
        std::vector<NodeId> rings;
        std::vector<int> sizes;
        if (cells.types[c] == CellType::polyhedron) {
            const auto [f0, f1] = cells.faces_of(c);
            for (std::int64_t f = f0; f < f1; ++f) {
                const auto ring = cells.face_nodes_of(f);
                rings.insert(rings.end(), ring.begin(), ring.end());
                sizes.push_back(static_cast<int>(ring.size()));
            }
        } else {
            const auto nodes = cells.nodes_of(c);
            const foam::FaceTable& table = foam::outward_faces(cells.types[c]);
            for (int k = 0; k < table.count; ++k) {
                for (int i = 0; i < table.size[k]; ++i) rings.push_back(nodes[static_cast<std::size_t>(table.node[k][i])]);
                sizes.push_back(table.size[k]);
            }
        }
        foam::push_cell_from_faces(rings, sizes, out);
    }
    return out;
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

// A mesh of polyhedra: every distinct face once in the NGON_n section
// "Faces" (the markers' faces first, as the markers have them; the face the
// two cells share once, from the first cell), the cells in the NFACE_n
// section "Cells" as signed face numbers (the shared face +9 in A, -9 in B:
// CGNS SIDS 7.3, a positive number's normal points out of the cell), the BCs
// PointLists of face numbers. It reads back equal; cgnscheck accepts it.
TEST(CgnsWrite, PolyhedraAreNgonFacesAndNfaceCells) {
    const auto dir = scratch_dir();
    const Mesh mesh = cgns_write_split_cube();
    write_cgns(dir / "cube.cgns", mesh);
    const ReadZone zone = read_test_cgns(dir / "cube.cgns");
    EXPECT_EQ(zone.cells, 2);
    ASSERT_EQ(zone.sections.size(), 2u);
    const ReadSection& faces = zone.sections[0];
    EXPECT_EQ(faces.section.name, "Faces");
    EXPECT_EQ(faces.section.type, cgns_code::NGON_n);
    EXPECT_EQ(faces.start, 1);
    EXPECT_EQ(faces.section.count, 9);
    EXPECT_EQ(faces.section.connectivity, (std::vector<cgns_size>{1, 3, 2, 1, 4, 3, 1, 2, 6, 5, 2, 3, 7, 6, 3, 4, 8, 7, 4,
                                                                  1, 5, 8, 5, 6, 7, 5, 7, 8, 1, 5, 7, 3}));
    EXPECT_EQ(faces.offsets, (std::vector<cgns_size>{0, 3, 6, 10, 14, 18, 22, 25, 28, 32}));
    const ReadSection& cells = zone.sections[1];
    EXPECT_EQ(cells.section.name, "Cells");
    EXPECT_EQ(cells.section.type, cgns_code::NFACE_n);
    EXPECT_EQ(cells.start, 10);
    EXPECT_EQ(cells.section.count, 2);
    EXPECT_EQ(cells.section.connectivity, (std::vector<cgns_size>{1, 7, 3, 4, 9, 2, 8, 5, 6, -9}));
    EXPECT_EQ(cells.offsets, (std::vector<cgns_size>{0, 5, 10}));
    ASSERT_EQ(zone.bcs.size(), 3u);
    const std::vector<std::vector<cgns_size>> points{{1, 2}, {3, 4, 5, 6}, {7, 8}};
    for (std::size_t k = 0; k < 3; ++k) {
        EXPECT_EQ(zone.bcs[k].name, mesh.markers[k].name);
        EXPECT_EQ(zone.bcs[k].point_set, "PointList");
        EXPECT_EQ(zone.bcs[k].location, cgns_code::FaceCenter);
        EXPECT_EQ(zone.bcs[k].points, points[k]);
    }
    // It reads back the same but for the cells, prisms from their faces (as OpenFOAM's are).
    Mesh expected = mesh;
    expected.cells = cgns_write_as_read(mesh.cells);
    EXPECT_EQ(expected.cells.types, (std::vector<CellType>{CellType::prism, CellType::prism}));
    EXPECT_TRUE(read_cgns(dir / "cube.cgns") == expected);
    // deform's output: the file with new coordinates, the rest kept.
    CgnsSource source;
    Mesh moved = read_cgns(dir / "cube.cgns", &source);
    for (double& x : moved.points) x = 2 * x + 1;
    write_cgns_points(dir / "moved.cgns", source, moved.points);
    EXPECT_TRUE(read_cgns(dir / "moved.cgns") == moved);
    if (cgns_tool_installed("cgnscheck")) {
        const CommandResult r = run_command("cgnscheck " + quoted(dir / "cube.cgns"));
        EXPECT_EQ(r.exit_code, 0) << r.out << r.err;
        EXPECT_EQ(r.out.find("ERROR"), std::string::npos) << r.out;
    }
}

// Beside a polyhedron, a cell of a fixed type is written as NFACE_n too (its
// outward faces) and reads back as that type from its faces (a polyhedron
// whose faces make a pyramid, a pyramid): the same faces, turned the same way.
TEST(CgnsWrite, FixedCellsBesidePolyhedraAreWrittenByTheirFaces) {
    Mesh mesh;
    // A unit cube (hexahedron 0-7) with a pyramid-shaped polyhedron on its top (apex 8).
    mesh.points = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0, 0, 0, 1, 1, 0, 1, 1, 1, 1, 0, 1, 1, 0.5, 0.5, 1.6};
    const NodeId hex[] = {0, 1, 2, 3, 4, 5, 6, 7};
    mesh.cells.push_back(CellType::hexahedron, hex);
    mesh.cells.push_polyhedron(std::vector<NodeId>{4, 7, 6, 5, 4, 5, 8, 5, 6, 8, 6, 7, 8, 7, 4, 8}, std::vector<int>{4, 3, 3, 3, 3});
    mesh.markers = {{"floor", {}}, {"roof", {}}};
    const NodeId floor[] = {0, 3, 2, 1};
    mesh.markers[0].elements.push_back(CellType::quadrilateral, floor);
    const NodeId roof[4][3] = {{4, 5, 8}, {5, 6, 8}, {6, 7, 8}, {7, 4, 8}};
    for (const auto& t : roof) mesh.markers[1].elements.push_back(CellType::triangle, t);
    const auto dir = scratch_dir();
    write_cgns(dir / "mixed.cgns", mesh);
    const ReadZone zone = read_test_cgns(dir / "mixed.cgns");
    ASSERT_EQ(zone.sections.size(), 2u);
    EXPECT_EQ(zone.sections[0].section.count, 10);  // 6 + 5 faces, one shared
    // The cube's top (its face 2, 5-6-7-8) is the pyramid's base turned round.
    EXPECT_EQ(zone.sections[1].section.connectivity, (std::vector<cgns_size>{1, 6, 7, 8, 9, 10, -6, 2, 3, 4, 5}));
    const Mesh back = read_cgns(dir / "mixed.cgns");
    EXPECT_EQ(back.points, mesh.points);
    EXPECT_TRUE(back.markers == mesh.markers);
    ASSERT_EQ(back.cells.size(), 2u);
    EXPECT_EQ(back.cells.types, (std::vector<CellType>{CellType::hexahedron, CellType::pyramid}));
    EXPECT_TRUE(back.cells == cgns_write_as_read(mesh.cells));
    for (std::size_t c = 0; c < 2; ++c)
        EXPECT_EQ(cgns_write_cell_faces(back.cells, c), cgns_write_cell_faces(mesh.cells, c)) << c;
    EXPECT_NEAR(element_shape_quality(back.cells, 0, 3, back.points), 1, 1e-12);  // the cube
    EXPECT_EQ(element_orientation(back.cells, 1, 3, back.points), 1);
    if (cgns_tool_installed("cgnscheck")) {
        const CommandResult r = run_command("cgnscheck " + quoted(dir / "mixed.cgns"));
        EXPECT_EQ(r.exit_code, 0) << r.out << r.err;
        EXPECT_EQ(r.out.find("ERROR"), std::string::npos) << r.out;
    }
}

// Polygons without polyhedra: a 2D mesh's cells in one NGON_n section (a
// MIXED section cannot hold NGON_n elements; its triangles too), its markers'
// edges as before; a 3D marker holding a polygon as an NGON_n section of
// its own. Both read back equal.
TEST(CgnsWrite, PolygonsAreNgonSections) {
    Mesh flat;
    flat.dim = 2;
    flat.points = {0, 0, 1, 0, 2, 0, 2, 1, 1, 1, 0, 1, 1.2, 0.5, 1, -1};
    const NodeId a[] = {0, 1, 6, 4, 5}, b[] = {1, 2, 3, 4, 6}, c[] = {0, 7, 1};
    flat.cells.push_back(CellType::polygon, a);
    flat.cells.push_back(CellType::polygon, b);
    flat.cells.push_back(CellType::triangle, c);
    const NodeId left[] = {5, 0};
    flat.markers = {{"left", {}}};
    flat.markers[0].elements.push_back(CellType::line, left);
    const auto dir = scratch_dir();
    write_cgns(dir / "flat.cgns", flat);
    ReadZone zone = read_test_cgns(dir / "flat.cgns");
    ASSERT_EQ(zone.sections.size(), 2u);
    EXPECT_EQ(zone.sections[0].section.type, cgns_code::NGON_n);
    EXPECT_EQ(zone.sections[0].section.connectivity, (std::vector<cgns_size>{1, 2, 7, 5, 6, 2, 3, 4, 5, 7, 1, 8, 2}));
    EXPECT_EQ(zone.sections[0].offsets, (std::vector<cgns_size>{0, 5, 10, 13}));
    EXPECT_EQ(zone.sections[1].section.type, cgns_code::BAR_2);
    EXPECT_EQ(zone.bcs[0].points, (std::vector<cgns_size>{4, 4}));
    EXPECT_TRUE(read_cgns(dir / "flat.cgns") == flat);

    // Two unit cubes side by side (hexahedra), their top one hexagon.
    Mesh boxes;
    boxes.points = {0, 0, 0, 1, 0, 0, 2, 0, 0, 0, 1, 0, 1, 1, 0, 2, 1, 0,
                    0, 0, 1, 1, 0, 1, 2, 0, 1, 0, 1, 1, 1, 1, 1, 2, 1, 1};
    const NodeId h0[] = {0, 1, 4, 3, 6, 7, 10, 9}, h1[] = {1, 2, 5, 4, 7, 8, 11, 10}, top[] = {6, 7, 8, 11, 10, 9};
    boxes.cells.push_back(CellType::hexahedron, h0);
    boxes.cells.push_back(CellType::hexahedron, h1);
    boxes.markers = {{"top", {}}};
    boxes.markers[0].elements.push_back(CellType::polygon, top);
    write_cgns(dir / "boxes.cgns", boxes);
    zone = read_test_cgns(dir / "boxes.cgns");
    ASSERT_EQ(zone.sections.size(), 2u);
    EXPECT_EQ(zone.sections[0].section.type, cgns_code::HEXA_8);
    EXPECT_EQ(zone.sections[1].section.type, cgns_code::NGON_n);
    EXPECT_EQ(zone.sections[1].section.connectivity, (std::vector<cgns_size>{7, 8, 9, 12, 11, 10}));
    EXPECT_TRUE(read_cgns(dir / "boxes.cgns") == boxes);
    if (cgns_tool_installed("cgnscheck"))
        for (const char* name : {"flat.cgns", "boxes.cgns"}) {
            const CommandResult r = run_command("cgnscheck " + quoted(dir / name));
            EXPECT_EQ(r.exit_code, 0) << name << r.out << r.err;
            EXPECT_EQ(r.out.find("ERROR"), std::string::npos) << name << "\n" << r.out;
        }
}

// With polyhedra the NGON_n section is "Faces": no marker may take that name.
TEST(CgnsWrite, APolyhedralMeshRefusesAMarkerCalledFaces) {
    Mesh mesh = cgns_write_split_cube();
    mesh.markers[1].name = "Faces";
    const auto dir = scratch_dir();
    EXPECT_THROW(write_cgns(dir / "faces.cgns", mesh), MeshError);
    EXPECT_FALSE(std::filesystem::exists(dir / "faces.cgns"));
    Mesh box = make_rect_box();  // without polyhedra "Faces" is a marker like any other
    box.markers[0].name = "Faces";
    EXPECT_NO_THROW(write_cgns(dir / "box.cgns", box));
    EXPECT_TRUE(read_cgns(dir / "box.cgns") == box);
}
