#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <limits>
#include <set>
#include <sstream>
#include <string>
#include <tuple>

#include "dgwarp/core/error.hpp"
#include "dgwarp/io/gmsh/gmsh.hpp"
#include "dgwarp/io/mesh_io.hpp"
#include "dgwarp/io/su2/su2.hpp"
#include "io/gmsh/gmsh_test_support.hpp"
#include "support/test_paths.hpp"

using namespace dgwarp;

// Gmsh 4.8 leaks a few small allocations of its own (element closures, caches)
// that outlive gmsh::finalize; with DGWARP_SANITIZE LeakSanitizer would fail
// every test that uses the library. Suppress leaks allocated inside libgmsh
// only (one definition for the whole test binary; ignored without LSan).
// Default visibility: the sanitizer build hides everything else, and the
// sanitizer runtime must find this function.
extern "C" __attribute__((visibility("default"))) const char* __lsan_default_suppressions() {
    return "leak:libgmsh.so\n";
}

namespace {

std::string to_text(const Mesh& mesh, int version) {
    std::ostringstream out;
    write_gmsh(out, mesh, version);
    return out.str();
}

Mesh round_trip(const Mesh& mesh, int version) {
    return read_gmsh_text("round_trip.msh", to_text(mesh, version));
}

// The lines of `text` between `begin` and `end` (exclusive).
std::vector<std::string> section(const std::string& text, const std::string& begin, const std::string& end) {
    std::istringstream in(text);
    std::vector<std::string> lines;
    std::string line;
    bool inside = false;
    while (std::getline(in, line)) {
        if (line == end) break;
        if (inside) lines.push_back(line);
        if (line == begin) inside = true;
    }
    return lines;
}

}  // namespace

TEST(GmshWrite, RoundTrip2dMixedMeshWithMarkers) {
    const Mesh m = test::mixed_2d_mesh();
    ASSERT_NO_THROW(validate(m));
    for (int version : {41, 22}) {
        SCOPED_TRACE(version);
        EXPECT_EQ(round_trip(m, version), m);
    }
}

TEST(GmshWrite, RoundTrip3dMixedMeshWithMarkers) {
    const Mesh m = test::mixed_3d_mesh();
    ASSERT_NO_THROW(validate(m));
    for (std::size_t i = 0; i < m.cells.size(); ++i) ASSERT_GT(test::vtk_corner_orientation(m, i), 0);
    for (int version : {41, 22}) {
        SCOPED_TRACE(version);
        EXPECT_EQ(round_trip(m, version), m);
    }
}

TEST(GmshWrite, CoordinatesRoundTripBitForBit) {
    Mesh m;
    m.dim = 3;
    m.points = {0.1, 1.0 / 3.0, -2.0 / 7.0, 1e-300, -1e300, std::numeric_limits<double>::denorm_min(),
                std::nextafter(1.0, 2.0), 123456789.123456789, -0.0, 0, 0, 1};
    const NodeId tet[] = {0, 1, 2, 3};
    m.cells.push_back(CellType::tetrahedron, tet);
    for (int version : {41, 22}) {
        const Mesh back = round_trip(m, version);
        ASSERT_EQ(back.points.size(), m.points.size());
        for (std::size_t i = 0; i < m.points.size(); ++i)
            EXPECT_EQ(std::signbit(back.points[i]), std::signbit(m.points[i])) << i;
        EXPECT_EQ(back, m);
    }
}

TEST(GmshWrite, Version22TextHasPhysicalGroupsAndGmshNodeOrder) {
    const Mesh m = test::mixed_3d_mesh();
    const std::string text = to_text(m, 22);
    EXPECT_EQ(text.substr(0, 34), "$MeshFormat\n2.2 0 8\n$EndMeshFormat");
    EXPECT_EQ(section(text, "$PhysicalNames", "$EndPhysicalNames"),
              (std::vector<std::string>{"4", "2 1 \"bottom\"", "2 2 \"far field\"", "2 3 \"unused\"",
                                        "3 4 \"domain\""}));
    const auto elements = section(text, "$Elements", "$EndElements");
    ASSERT_EQ(elements.size(), 1u + 4 + 4 + 5);
    EXPECT_EQ(elements[0], "13");
    EXPECT_EQ(elements[1], "1 3 2 1 1 1 4 3 2");  // hex bottom quad in "bottom"
    EXPECT_EQ(elements[8], "8 3 2 2 2 1 4 3 2");  // the same quad in "far field"
    // Cells: tag type 2 physical 4, entity 1; the prism back in Gmsh order.
    EXPECT_EQ(elements[9], "9 5 2 4 1 1 2 3 4 5 6 7 8");
    EXPECT_EQ(elements[12], "12 6 2 4 1 9 11 10 12 14 13");
    EXPECT_EQ(elements[13], "13 7 2 4 1 15 16 17 18 19");
}

TEST(GmshWrite, Version41TextHasEntitiesAndOneBlockPerTypeRun) {
    const Mesh m = test::mixed_2d_mesh();
    const std::string text = to_text(m, 41);
    EXPECT_EQ(text.substr(0, 34), "$MeshFormat\n4.1 0 8\n$EndMeshFormat");
    const auto entities = section(text, "$Entities", "$EndEntities");
    ASSERT_EQ(entities.size(), 1u + 5 + 1);
    EXPECT_EQ(entities[0], "0 5 1 0");  // 5 curves (markers), 1 surface (cells)
    const auto nodes = section(text, "$Nodes", "$EndNodes");
    ASSERT_EQ(nodes.size(), 2u + 6 + 6);
    EXPECT_EQ(nodes[0], "1 6 1 6");
    EXPECT_EQ(nodes[1], "2 1 0 6");
    const auto elements = section(text, "$Elements", "$EndElements");
    // Blocks: wall, outlet, top side, corner (no block for the empty marker),
    // then the cells as runs triangle, quadrangle, triangle.
    EXPECT_EQ(elements[0], "7 10 1 10");
    EXPECT_EQ(elements[1], "1 1 1 2");
    EXPECT_EQ(elements[elements.size() - 6], "2 1 2 1");
    EXPECT_EQ(elements[elements.size() - 4], "2 1 3 1");
    EXPECT_EQ(elements[elements.size() - 3], "9 2 5 6 3");
    EXPECT_EQ(elements[elements.size() - 2], "2 1 2 1");
}

TEST(GmshWrite, WritesAFileAtomicallyThatReadsBack) {
    const auto dir = test::scratch_dir();
    const Mesh m = test::mixed_3d_mesh();
    write_gmsh(dir / "mesh.msh", m, 22);
    EXPECT_EQ(read_gmsh(dir / "mesh.msh"), m);
    write_mesh(dir / "via_extension.msh", m);  // 4.1 by default
    EXPECT_EQ(read_mesh(dir / "via_extension.msh"), m);
    std::ifstream in(dir / "via_extension.msh");
    std::string first, second;
    std::getline(in, first);
    std::getline(in, second);
    EXPECT_EQ(second, "4.1 0 8");
}

TEST(GmshWrite, RejectsWhatItCannotWrite) {
    const Mesh m = test::mixed_2d_mesh();
    std::ostringstream out;
    EXPECT_THROW(write_gmsh(out, m, 40), FormatError);
    Mesh quoted = m;
    quoted.markers[0].name = "say \"wall\"";
    EXPECT_THROW(write_gmsh(out, quoted, 41), MeshError);
    Mesh vertices = m;
    const NodeId v[] = {0};
    vertices.markers[1].elements.push_back(CellType::vertex, v);
    ASSERT_NO_THROW(validate(vertices));
    EXPECT_THROW(write_gmsh(out, vertices, 41), MeshError);
    Mesh broken = m;
    broken.cells.nodes[0] = 99;
    EXPECT_THROW(write_gmsh(out, broken, 22), MeshError);
    // A failed write leaves no file behind.
    const auto dir = test::scratch_dir();
    EXPECT_THROW(write_gmsh(dir / "bad.msh", broken, 41), MeshError);
    EXPECT_FALSE(std::filesystem::exists(dir / "bad.msh"));
}

// ---- Gmsh's own library opens what we write. ----

namespace {

// Opens `file` with Gmsh and checks it sees the nodes, cells, boundary
// elements and named physical groups of `m`.
void expect_gmsh_sees(const std::filesystem::path& file, const Mesh& m) {
    test::GmshSession session;
    gmsh::open(file.string());
    EXPECT_EQ(test::gmsh_node_count(), m.num_points());

    // Node coordinates, exactly.
    std::vector<std::size_t> tags;
    std::vector<double> coord, parametric;
    gmsh::model::mesh::getNodes(tags, coord, parametric, -1, -1, false, false);
    for (std::size_t k = 0; k < tags.size(); ++k)
        for (int c = 0; c < m.dim; ++c)
            ASSERT_EQ(coord[3 * k + c], m.points[(tags[k] - 1) * m.dim + c]) << "node tag " << tags[k];

    std::map<int, std::size_t> cells;
    for (const auto& [type, n] : test::cell_type_map(m.cells)) cells[type == CellType::triangle ? 2
                                                                     : type == CellType::quadrilateral ? 3
                                                                     : type == CellType::tetrahedron ? 4
                                                                     : type == CellType::hexahedron ? 5
                                                                     : type == CellType::prism ? 6
                                                                                               : 7] = n;
    EXPECT_EQ(test::gmsh_element_counts(m.dim), cells);

    std::set<std::tuple<int, int, std::string>> expected_groups, groups;
    for (std::size_t i = 0; i < m.markers.size(); ++i)
        expected_groups.insert({m.dim - 1, static_cast<int>(i) + 1, m.markers[i].name});
    expected_groups.insert({m.dim, static_cast<int>(m.markers.size()) + 1, "domain"});
    gmsh::vectorpair dim_tags;
    gmsh::model::getPhysicalGroups(dim_tags);
    for (const auto& [dim, tag] : dim_tags) {
        std::string name;
        gmsh::model::getPhysicalName(dim, tag, name);
        groups.insert({dim, tag, name});
    }
    // Gmsh drops a physical group without elements ("unused") when reading.
    for (const auto& g : groups) EXPECT_TRUE(expected_groups.count(g)) << std::get<2>(g);
    for (std::size_t i = 0; i < m.markers.size(); ++i) {
        if (m.markers[i].elements.empty()) continue;
        EXPECT_TRUE(groups.count({m.dim - 1, static_cast<int>(i) + 1, m.markers[i].name})) << m.markers[i].name;
        EXPECT_EQ(test::gmsh_group_size(m.dim - 1, static_cast<int>(i) + 1), m.markers[i].elements.size())
            << m.markers[i].name;
    }
    EXPECT_EQ(test::gmsh_group_size(m.dim, static_cast<int>(m.markers.size()) + 1), m.cells.size());

    if (m.dim == 3) {
        // Gmsh's Jacobian determinant at each reference cell's centre is
        // positive: our VTK -> Gmsh node permutation matches Gmsh's orientation.
        const std::pair<int, std::vector<double>> centres[] = {
            {4, {0.25, 0.25, 0.25}}, {5, {0, 0, 0}}, {6, {1.0 / 3, 1.0 / 3, 0}}, {7, {0, 0, 0.25}}};
        for (const auto& [type, centre] : centres) {
            std::vector<double> jacobians, determinants, points;
            gmsh::model::mesh::getJacobians(type, centre, jacobians, determinants, points);
            EXPECT_EQ(determinants.size(), cells[type]) << "type " << type;
            for (double d : determinants) EXPECT_GT(d, 0) << "Gmsh type " << type;
        }
    }
}

}  // namespace

TEST(GmshLibrary, OpensOur3dMeshInBothVersions) {
    const auto dir = test::scratch_dir();
    const Mesh m = test::mixed_3d_mesh();
    for (int version : {41, 22}) {
        SCOPED_TRACE(version);
        const auto file = dir / ("mixed3d_" + std::to_string(version) + ".msh");
        write_gmsh(file, m, version);
        expect_gmsh_sees(file, m);
    }
}

TEST(GmshLibrary, OpensOur2dMeshInBothVersions) {
    const auto dir = test::scratch_dir();
    const Mesh m = test::mixed_2d_mesh();
    for (int version : {41, 22}) {
        SCOPED_TRACE(version);
        const auto file = dir / ("mixed2d_" + std::to_string(version) + ".msh");
        write_gmsh(file, m, version);
        expect_gmsh_sees(file, m);
    }
}

// ---- Every real mesh: SU2 -> MSH 4.1 / 2.2 -> Mesh -> SU2 -> Mesh. ----

TEST(GmshWrite, RoundTripsEveryRealSu2Mesh) {
    DGWARP_REQUIRE_SHARED_MESHES();
    const auto files = test::su2_meshes();
    const auto dir = test::scratch_dir();
    for (const auto& file : files) {
        SCOPED_TRACE(file.filename().string());
        const Mesh m = read_mesh(file);
        for (int version : {41, 22}) {
            SCOPED_TRACE(version);
            const auto msh = dir / ("mesh_" + std::to_string(version) + ".msh");
            write_gmsh(msh, m, version);
            const Mesh back = read_gmsh(msh);
            EXPECT_EQ(back, m);
            write_mesh(dir / "mesh.su2", back);
            EXPECT_EQ(read_mesh(dir / "mesh.su2"), m);
        }
    }
}
