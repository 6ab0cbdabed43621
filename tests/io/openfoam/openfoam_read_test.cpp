// Reading OpenFOAM polyMesh folders: the cases blockMesh and gmshToFoam made
// (tests/data/openfoam/README.md), ascii and binary, checked against the files
// parsed independently; the cell order's rule on every cell type.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <random>
#include <tuple>

#include "dgwarp/core/error.hpp"
#include "dgwarp/io/mesh_io.hpp"
#include "dgwarp/io/openfoam/openfoam.hpp"
#include "dgwarp/io/openfoam/openfoam_poly_mesh.hpp"
#include "dgwarp/quality/cell_quality.hpp"
#include "io/openfoam/openfoam_test_support.hpp"

using namespace dgwarp;
using namespace dgwarp::test;

namespace {

struct FoamMarkerCount {
    std::string name;
    std::size_t faces;
};

void expect_markers(const Mesh& mesh, const std::vector<FoamMarkerCount>& expected) {
    ASSERT_EQ(mesh.markers.size(), expected.size());
    for (std::size_t m = 0; m < expected.size(); ++m) {
        EXPECT_EQ(mesh.markers[m].name, expected[m].name);
        EXPECT_EQ(mesh.markers[m].elements.size(), expected[m].faces) << expected[m].name;
    }
}

}  // namespace

TEST(OpenFoamRead, BlockMeshCavityIsTwelveValidHexahedraWithItsPatches) {
    OpenFoamSource source;
    const Mesh mesh = read_openfoam(openfoam_case("cavity"), {}, &source);
    EXPECT_EQ(mesh.dim, 3);
    EXPECT_EQ(mesh.num_points(), 40u);
    const auto counts = count_by_type(mesh.cells);
    EXPECT_EQ(counts[static_cast<int>(CellType::hexahedron)], 12);
    EXPECT_EQ(mesh.cells.size(), 12u);
    expect_markers(mesh, {{"movingWall", 4}, {"fixedWalls", 10}, {"frontAndBack", 24}});
    for (const Marker& m : mesh.markers)
        for (CellType t : m.elements.types) EXPECT_EQ(t, CellType::quadrilateral);
    expect_mesh_matches_ascii_files(mesh, openfoam_files("cavity"));
    EXPECT_EQ(source.points_format, foam::Format::ascii);
    EXPECT_EQ(source.poly_mesh, openfoam_case("cavity") / "constant" / "polyMesh");
    ASSERT_EQ(source.patches.size(), 3u);
    EXPECT_EQ(source.patches[0].type, "wall");
    EXPECT_EQ(source.patches[2].type, "empty");
    EXPECT_EQ(source.patches[2].entries, std::vector<std::string>{"inGroups 1(empty);"});
}

TEST(OpenFoamRead, GmshToFoamMeshHasEveryCellTypeAllValid) {
    const Mesh mesh = read_openfoam(openfoam_case("mixed"));
    EXPECT_EQ(mesh.num_points(), 102u);
    const auto counts = count_by_type(mesh.cells);
    EXPECT_EQ(counts[static_cast<int>(CellType::tetrahedron)], 170);
    EXPECT_EQ(counts[static_cast<int>(CellType::hexahedron)], 8);
    EXPECT_EQ(counts[static_cast<int>(CellType::prism)], 26);
    EXPECT_EQ(counts[static_cast<int>(CellType::pyramid)], 4);
    EXPECT_EQ(mesh.cells.size(), 208u);
    expect_markers(mesh, {{"bottom", 17}, {"sides", 87}, {"top", 28}});
    const auto faces = count_by_type(mesh.markers[1].elements);
    EXPECT_GT(faces[static_cast<int>(CellType::triangle)], 0);
    EXPECT_GT(faces[static_cast<int>(CellType::quadrilateral)], 0);
    expect_mesh_matches_ascii_files(mesh, openfoam_files("mixed"));
}

TEST(OpenFoamRead, BinaryCasesReadAsTheirAsciiOriginals) {
    for (const std::string name : {"cavity", "mixed"}) {
        OpenFoamSource source;
        const Mesh binary = read_openfoam(openfoam_case(name + "-binary"), {}, &source);
        EXPECT_EQ(source.points_format, foam::Format::binary);
        EXPECT_TRUE(binary == read_openfoam(openfoam_case(name))) << name;
        // The faces file is a faceCompactList there, a faceList in ascii.
        EXPECT_NE(slurp(openfoam_case(name + "-binary") / "constant/polyMesh/faces").find("faceCompactList"),
                  std::string::npos);
    }
}

TEST(OpenFoamRead, CaseFolderPolyMeshFolderAndReadMeshAgree) {
    const Mesh from_case = read_openfoam(openfoam_case("mixed"));
    EXPECT_TRUE(read_openfoam(openfoam_case("mixed") / "constant" / "polyMesh") == from_case);
    EXPECT_TRUE(read_mesh(openfoam_case("mixed")) == from_case);
    EXPECT_TRUE(read_mesh(openfoam_case("mixed").string() + "/") == from_case);
    MeshExtras extras;
    EXPECT_TRUE(read_mesh(openfoam_case("mixed"), {}, {}, extras) == from_case);
    ASSERT_TRUE(extras.openfoam.has_value());
    EXPECT_EQ(extras.openfoam->patches.size(), 3u);
    EXPECT_EQ(extras.openfoam->patches[0].entries, std::vector<std::string>{"physicalType patch;"});
}

TEST(OpenFoamRead, ProgressReachesOne) {
    std::vector<double> seen;
    read_openfoam(openfoam_case("cavity"), [&](double f) { seen.push_back(f); });
    ASSERT_FALSE(seen.empty());
    EXPECT_TRUE(std::is_sorted(seen.begin(), seen.end()));
    EXPECT_EQ(seen.back(), 1.0);
}

namespace {

/// Six times the volume the faces enclose (divergence theorem from the face
/// centres, each face's pieces (centre, node k, node k+1)), faces pointing out.
double enclosed_volume_6(const std::vector<double>& p, const std::vector<std::vector<NodeId>>& faces) {
    double v = 0;
    for (const auto& f : faces) {
        double c[3] = {0, 0, 0};
        for (NodeId n : f)
            for (int d = 0; d < 3; ++d) c[d] += p[3 * static_cast<std::size_t>(n) + d] / static_cast<double>(f.size());
        for (std::size_t k = 0; k < f.size(); ++k) {
            const double* a = &p[3 * static_cast<std::size_t>(f[k])];
            const double* b = &p[3 * static_cast<std::size_t>(f[(k + 1) % f.size()])];
            v += c[0] * (a[1] * b[2] - a[2] * b[1]) - c[1] * (a[0] * b[2] - a[2] * b[0]) + c[2] * (a[0] * b[1] - a[1] * b[0]);
        }
    }
    return v;
}

}  // namespace

TEST(OpenFoamRead, PolyhedraAreKeptWithTheirFacesPointingOut) {
    // polyDualMesh of the cavity (8 hexahedra, 32 polyhedra) and snappyHexMesh's
    // sphere in a box (576 hexahedra, 272 polyhedra; boundary faces of 5 and 6
    // points), both "Mesh OK." for checkMesh.
    for (const auto& [name, hexahedra, polyhedra, polygons] :
         {std::tuple{"cavity-polyhedral", 8, 32, -1}, std::tuple{"snappy-sphere", 576, 272, 80}}) {
        SCOPED_TRACE(name);
        const Mesh mesh = read_openfoam(openfoam_case(name));
        const auto counts = count_by_type(mesh.cells);
        EXPECT_EQ(counts[static_cast<std::size_t>(CellType::hexahedron)], hexahedra);
        EXPECT_EQ(counts[static_cast<std::size_t>(CellType::polyhedron)], polyhedra);
        std::int64_t boundary_polygons = 0;
        for (const Marker& m : mesh.markers) boundary_polygons += count_by_type(m.elements)[static_cast<std::size_t>(CellType::polygon)];
        if (polygons >= 0) {
            EXPECT_EQ(boundary_polygons, polygons);
        }
        // Each polyhedron: positive orientation and quality, its faces enclosing a
        // positive volume; all cells' volumes together that of the boundary faces.
        double cells_volume = 0, hex_volume = 0;
        for (std::size_t c = 0; c < mesh.cells.size(); ++c) {
            if (mesh.cells.types[c] != CellType::polyhedron) {
                // A hexahedron's faces from the reader's own table.
                const foam::FaceTable& t = foam::outward_faces(mesh.cells.types[c]);
                std::vector<std::vector<NodeId>> faces;
                for (int k = 0; k < t.count; ++k) {
                    faces.emplace_back();
                    for (int i = 0; i < t.size[k]; ++i) faces.back().push_back(mesh.cells.nodes_of(c)[static_cast<std::size_t>(t.node[k][i])]);
                }
                hex_volume += enclosed_volume_6(mesh.points, faces);
                continue;
            }
            EXPECT_EQ(element_orientation(mesh.cells, c, 3, mesh.points), 1) << "cell " << c;
            EXPECT_GT(element_shape_quality(mesh.cells, c, 3, mesh.points), 0.0) << "cell " << c;
            std::vector<std::vector<NodeId>> faces;
            const auto [f0, f1] = mesh.cells.faces_of(c);
            for (std::int64_t f = f0; f < f1; ++f) faces.emplace_back(mesh.cells.face_nodes_of(f).begin(), mesh.cells.face_nodes_of(f).end());
            const double v = enclosed_volume_6(mesh.points, faces);
            EXPECT_GT(v, 0.0) << "cell " << c;
            cells_volume += v;
        }
        std::vector<std::vector<NodeId>> boundary;
        for (const Marker& m : mesh.markers)
            for (std::size_t e = 0; e < m.elements.size(); ++e)
                boundary.emplace_back(m.elements.nodes_of(e).begin(), m.elements.nodes_of(e).end());
        const double total = enclosed_volume_6(mesh.points, boundary);
        EXPECT_NEAR(cells_volume + hex_volume, total, 1e-9 * std::abs(total));
    }
}

TEST(OpenFoamRead, ADecomposedCaseWithPolyhedraReadsAsTheWholeCase) {
    // decomposePar (simple, 2 × 1 × 1) of the snappy case: the processors give
    // the serial case's cells, polyhedra and their faces included, and markers.
    EXPECT_TRUE(read_openfoam(openfoam_case("snappy-sphere-decomposed")) == read_openfoam(openfoam_case("snappy-sphere")));
}

TEST(OpenFoamRead, APolyhedronWhoseFacesDoNotCloseItIsAParseError) {
    // The snappy case with one face of a polyhedron given one node less:
    // its cells' edges no longer pair up.
    const auto dir = openfoam_case("snappy-sphere") / "constant" / "polyMesh";
    PolyMeshFiles files{foam::read_mesh_file(dir, "points"), foam::read_mesh_file(dir, "faces"),
                        foam::read_mesh_file(dir, "owner"), foam::read_mesh_file(dir, "neighbour"),
                        foam::read_mesh_file(dir, "boundary")};
    // Damage a pentagon of the faces file: "5(a b c d e)" -> "4(a b c d)".
    const std::size_t at = files.faces.find("\n5(");
    ASSERT_NE(at, std::string::npos);
    const std::size_t close = files.faces.find(')', at);
    const std::size_t last = files.faces.rfind(' ', close);
    files.faces = files.faces.substr(0, at + 1) + "4" + files.faces.substr(at + 2, last - at - 2) + files.faces.substr(close);
    try {
        read_openfoam_files("snappy-damaged", files);
        FAIL() << "no error";
    } catch (const ParseError& e) {
        const std::string what = e.what();
        EXPECT_NE(what.find("to close"), std::string::npos) << what;
    }
}

TEST(OpenFoamRead, NotACaseAndBrokenDecomposedCasesAreRefusedClearly) {
    const auto dir = scratch_dir();
    EXPECT_THROW(read_openfoam(dir / "missing"), IoError);
    std::filesystem::create_directories(dir / "empty");
    try {
        read_mesh(dir / "empty");
        FAIL();
    } catch (const FormatError& e) {
        EXPECT_NE(std::string(e.what()).find("not an OpenFOAM case"), std::string::npos) << e.what();
    }
    // A decomposed case with an empty processor polyMesh: the file it misses.
    std::filesystem::create_directories(dir / "decomposed" / "processor0" / "constant" / "polyMesh");
    try {
        read_mesh(dir / "decomposed");
        FAIL();
    } catch (const IoError& e) {
        EXPECT_EQ(e.file(), (dir / "decomposed" / "processor0" / "constant" / "polyMesh" / "points").string()) << e.what();
    }
    // processor0 and processor2: processor1 is missing.
    std::filesystem::create_directories(dir / "decomposed" / "processor2" / "constant" / "polyMesh");
    try {
        read_mesh(dir / "decomposed");
        FAIL();
    } catch (const FormatError& e) {
        EXPECT_NE(std::string(e.what()).find("processor1 is missing"), std::string::npos) << e.what();
    }
    // OpenFOAM's collated layout.
    std::filesystem::create_directories(dir / "collated" / "processors2" / "constant" / "polyMesh");
    try {
        read_mesh(dir / "collated");
        FAIL();
    } catch (const FormatError& e) {
        EXPECT_NE(std::string(e.what()).find("collated"), std::string::npos) << e.what();
    }
    // One processor's polyMesh on its own: its processor patches say what it is.
    try {
        read_mesh(openfoam_case("mixed-decomposed") / "processor1");
        FAIL();
    } catch (const FormatError& e) {
        EXPECT_NE(std::string(e.what()).find("one processor's part of a decomposed case"), std::string::npos) << e.what();
    }
}

// decomposePar's processors, read as one mesh, are the case they came from.
TEST(OpenFoamRead, DecomposedCasesReadAsTheWholeCase) {
    for (const std::string name : {"mixed", "cavity-binary"}) {
        OpenFoamSource source;
        const Mesh whole = read_openfoam(openfoam_case(name));
        const Mesh decomposed = read_openfoam(openfoam_case(name + "-decomposed"), {}, &source);
        EXPECT_TRUE(decomposed == whole) << name;
        ASSERT_EQ(source.processors.size(), 2u);
        EXPECT_EQ(source.patches.size(), whole.markers.size());
        EXPECT_TRUE(source.poly_mesh.empty());
        for (const OpenFoamProcessor& p : source.processors) {
            EXPECT_EQ(p.points_format, name == "mixed" ? foam::Format::ascii : foam::Format::binary);
            // Its points, taken from the whole mesh's, are its own file's in its order: the data
            // between the list's brackets is the same, byte for byte.
            const std::string file = slurp(p.poly_mesh / "points");
            const std::string ours = openfoam_points_text(processor_points(p, decomposed.points), p.points_format, "x");
            const auto data = [](const std::string& text) {
                const std::size_t open = text.find("\n(", text.find("// * *"));
                return text.substr(open, text.rfind(')') - open);
            };
            if (p.points_format == foam::Format::binary) {
                EXPECT_EQ(data(ours), data(file));
            } else {
                EXPECT_EQ(foam_body_numbers(ours), foam_body_numbers(file));
            }
        }
    }
}

// channel395's cyclic patches decomposed two ways: the processorCyclic
// patches' faces are their referPatch's again, in the case's order.
TEST(OpenFoamRead, ProcessorCyclicFacesAreTheirCyclicPatchesFaces) {
    const Mesh whole = read_openfoam(openfoam_case("channel-cyclic"));
    for (const std::string name : {"channel-cyclic-decomposed", "channel-cyclic-decomposed-4"}) {
        SCOPED_TRACE(name);
        OpenFoamSource source;
        const Mesh decomposed = read_openfoam(openfoam_case(name), {}, &source);
        EXPECT_TRUE(decomposed == whole);
        // The patches are the case's (no processor or processorCyclic one), with their entries.
        ASSERT_EQ(source.patches.size(), 10u);
        EXPECT_EQ(source.patches[6].type, "cyclic");
        EXPECT_NE(std::find(source.patches[6].entries.begin(), source.patches[6].entries.end(),
                            "neighbourPatch inout1_half1;"),
                  source.patches[6].entries.end());
        // decomposePar made processorCyclic patches (inout's faces whose images are on the other processor).
        bool any = false;
        for (const OpenFoamProcessor& p : source.processors)
            any = any || slurp(p.poly_mesh / "boundary").find("processorCyclic;") != std::string::npos;
        EXPECT_TRUE(any);
    }
    // One processor read alone keeps none of them as markers.
    const OpenFoamProcessorMesh part =
        read_openfoam_processor(openfoam_processor_meshes(openfoam_case("channel-cyclic-decomposed"))[0]);
    EXPECT_EQ(part.mesh.markers.size(), part.patches.size());
    EXPECT_EQ(part.patches.size(), 10u);
}

// The cell order's rule (openfoam_poly_mesh.hpp): whatever the order of a
// cell's faces and their first nodes, order_cell gives the same cell, with
// positive orientation, bounded by those faces.
TEST(OpenFoamRead, DecomposedCasesWhoseProcessorsDisagreeAreRefused) {
    const auto dir = scratch_dir();
    std::filesystem::copy(openfoam_case("mixed-decomposed"), dir / "case", std::filesystem::copy_options::recursive);
    const auto addressing = dir / "case" / "processor1" / "constant" / "polyMesh" / "pointProcAddressing";
    const std::string good = slurp(addressing);
    // Processor 1's first two points swapped in the case's numbering: shared points at two places.
    std::string bad = good;
    const std::size_t open = bad.find("\n(\n") + 3;
    const std::size_t second = bad.find('\n', open) + 1, third = bad.find('\n', second) + 1;
    bad = bad.substr(0, open) + bad.substr(second, third - second) + bad.substr(open, second - open) + bad.substr(third);
    write_text(addressing, bad);
    try {
        read_mesh(dir / "case");
        FAIL();
    } catch (const ParseError& e) {
        EXPECT_NE(e.file().find("processor1"), std::string::npos) << e.what();
    }
    // One label too few: the list without its first label.
    const std::size_t paren = good.find("\n(\n"), count = good.rfind('\n', paren - 1) + 1;
    const auto labels = foam_ascii_labels(good);
    std::string shorter = good.substr(0, count) + std::to_string(labels.size() - 1) + "\n(\n";
    for (std::size_t i = 1; i < labels.size(); ++i) shorter += std::to_string(labels[i]) + "\n";
    shorter += ")\n";
    write_text(addressing, shorter);
    try {
        read_mesh(dir / "case");
        FAIL();
    } catch (const ParseError& e) {
        EXPECT_EQ(e.file(), addressing.string()) << e.what();
        EXPECT_NE(e.expected().find("one per point"), std::string::npos) << e.what();
    }
}

TEST(OpenFoamRead, CellOrderDependsOnlyOnTheFacesAsCycles) {
    std::mt19937 rng(15);
    // Ideal elements (positive orientation in VTK order).
    const double s3 = std::sqrt(3.0);
    const std::vector<std::pair<CellType, std::vector<double>>> ideal = {
        {CellType::tetrahedron, {0, 0, 0, 1, 0, 0, 0.5, s3 / 2, 0, 0.5, s3 / 6, std::sqrt(2.0 / 3.0)}},
        {CellType::pyramid, {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0, 0.5, 0.5, 1 / std::sqrt(2.0)}},
        {CellType::prism, {0, 0, 0, 0.5, s3 / 2, 0, 1, 0, 0, 0, 0, 1, 0.5, s3 / 2, 1, 1, 0, 1}},
        {CellType::hexahedron, {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0, 0, 0, 1, 1, 0, 1, 1, 1, 1, 0, 1, 1}},
    };
    for (const auto& [type, coords] : ideal) {
        const int n = nodes_per_cell(type);
        ASSERT_EQ(cell_orientation(type, coords, 3), 1);
        for (int trial = 0; trial < 200; ++trial) {
            // Node k of the element gets a random id; ids index a point array.
            std::vector<NodeId> id(static_cast<std::size_t>(n));
            std::iota(id.begin(), id.end(), 0);
            std::shuffle(id.begin(), id.end(), rng);
            for (auto& v : id) v = v * 7 + 3;
            const foam::FaceTable& t = foam::outward_faces(type);
            std::vector<int> order(static_cast<std::size_t>(t.count));
            std::iota(order.begin(), order.end(), 0);
            std::shuffle(order.begin(), order.end(), rng);
            foam::CellFaces faces;
            for (int k : order) {
                const int size = t.size[k];
                const int shift = static_cast<int>(rng() % static_cast<unsigned>(size));
                faces.size[faces.count] = size;
                for (int i = 0; i < size; ++i)
                    faces.node[faces.count][i] = id[static_cast<std::size_t>(t.node[k][(i + shift) % size])];
                ++faces.count;
            }
            const foam::OrderedCell c = foam::order_cell(faces);
            ASSERT_EQ(c.shape, foam::CellShape::ok);
            ASSERT_EQ(c.type, type);
            // The rule: the smallest id first (a pyramid: the smallest of its base).
            const NodeId smallest = *std::min_element(id.begin(), id.begin() + (type == CellType::pyramid ? 4 : n));
            EXPECT_EQ(c.node[0], smallest);
            // Positive orientation: the ordered cell's coordinates, taken from the ideal element.
            std::vector<double> x;
            for (int i = 0; i < n; ++i) {
                const auto k = static_cast<std::size_t>(std::find(id.begin(), id.end(), c.node[static_cast<std::size_t>(i)]) - id.begin());
                x.insert(x.end(), coords.begin() + static_cast<std::ptrdiff_t>(3 * k),
                         coords.begin() + static_cast<std::ptrdiff_t>(3 * k + 3));
            }
            EXPECT_EQ(cell_orientation(type, x, 3), 1) << cell_type_name(type);
            // The same faces given in another order and rotation: the same cell.
            foam::CellFaces again = faces;
            std::reverse(again.node.begin(), again.node.begin() + again.count);
            std::reverse(again.size.begin(), again.size.begin() + again.count);
            for (int k = 0; k < again.count; ++k)
                std::rotate(again.node[k].begin(), again.node[k].begin() + 1, again.node[k].begin() + again.size[k]);
            EXPECT_EQ(foam::order_cell(again).node, c.node);
        }
    }
}

TEST(OpenFoamRead, FacesThatDoNotCloseACellOrAreTooManyAreNotACell) {
    // A hexahedron's faces with one face turned inward: six quadrilaterals, not closed.
    const foam::FaceTable& t = foam::outward_faces(CellType::hexahedron);
    foam::CellFaces f;
    f.count = 6;
    for (int k = 0; k < 6; ++k) {
        f.size[k] = 4;
        for (int i = 0; i < 4; ++i) f.node[k][i] = t.node[k][i];
    }
    EXPECT_EQ(foam::order_cell(f).shape, foam::CellShape::ok);
    std::reverse(f.node[2].begin(), f.node[2].end());
    EXPECT_EQ(foam::order_cell(f).shape, foam::CellShape::not_closed);
    // Five quadrilaterals, or a pentagon: polyhedra.
    f.count = 5;
    EXPECT_EQ(foam::order_cell(f).shape, foam::CellShape::polyhedron);
    f.count = 6;
    f.size[0] = 5;
    EXPECT_EQ(foam::order_cell(f).shape, foam::CellShape::polyhedron);
}

TEST(OpenFoamRead, LabelsInEveryFormReadAsTheirValues) {
    // The usual label (plain digits before a delimiter) and the others: a
    // sign, leading zeros, a comment or a parenthesis right after the digits.
    const std::string header = "FoamFile\n{\n    version 2.0;\n    format ascii;\n    class labelList;\n    object owner;\n}\n";
    const std::vector<std::int32_t> labels = foam::read_label_list_file(
        "owner", header + "7\n(\n0007\n12// a comment\n13/* another */\n+4\n000000000000000005\t6\n0000000000000000000000000009)\n");
    EXPECT_EQ(labels, (std::vector<std::int32_t>{7, 12, 13, 4, 5, 6, 9}));
    // Digits run into a letter, or more digits than a label holds: refused.
    EXPECT_THROW(foam::read_label_list_file("owner", header + "2\n(\n1\n2x\n)\n"), ParseError);
    EXPECT_THROW(foam::read_label_list_file("owner", header + "2\n(\n1\n" + std::string(40, '9') + "\n)\n"), ParseError);
}
