// Writing OpenFOAM polyMesh folders: round trips of the OpenFOAM cases and of
// the real 3D SU2 meshes, OpenFOAM's face order and orientation checked by
// brute force, points-only files, and meshes a polyMesh cannot hold.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <tuple>

#include "dgwarp/core/error.hpp"
#include "dgwarp/io/mesh_io.hpp"
#include "dgwarp/io/openfoam/openfoam.hpp"
#include "dgwarp/io/openfoam/openfoam_poly_mesh.hpp"
#include "dgwarp/quality/mesh_quality.hpp"
#include "io/openfoam/openfoam_test_support.hpp"

using namespace dgwarp;
using namespace dgwarp::test;

namespace {

using Vec3 = std::array<double, 3>;

Vec3 foam_point(const std::vector<double>& points, NodeId n) {
    return {points[3 * static_cast<std::size_t>(n)], points[3 * static_cast<std::size_t>(n) + 1],
            points[3 * static_cast<std::size_t>(n) + 2]};
}

/// The cell's centroid (mean of its nodes).
Vec3 foam_cell_centre(const Mesh& mesh, std::size_t c) {
    Vec3 s{};
    const auto nodes = mesh.cells.nodes_of(c);
    for (NodeId n : nodes) {
        const Vec3 p = foam_point(mesh.points, n);
        for (int d = 0; d < 3; ++d) s[d] += p[d] / static_cast<double>(nodes.size());
    }
    return s;
}

/// OpenFOAM's rules on a written polyMesh, checked on its files as parsed
/// by the test support (ascii): internal faces first, owner < neighbour,
/// sorted by owner then neighbour; each face's normal (Newell's) points out
/// of its owner and into its neighbour, measured from the cells' centroids
/// of `mesh` (valid cells: a face points away from the centroid of a cell
/// it bounds).
void expect_openfoam_face_rules(const Mesh& mesh, const PolyMeshFiles& files) {
    const auto faces = foam_ascii_faces(files.faces);
    const auto owner = foam_ascii_labels(files.owner);
    const auto neighbour = foam_ascii_labels(files.neighbour);
    ASSERT_EQ(owner.size(), faces.size());
    for (std::size_t f = 0; f < neighbour.size(); ++f) {
        ASSERT_LT(owner[f], neighbour[f]) << f;
        if (f > 0) {
            ASSERT_TRUE(owner[f - 1] < owner[f] || (owner[f - 1] == owner[f] && neighbour[f - 1] < neighbour[f])) << f;
        }
    }
    for (std::size_t f = 0; f < faces.size(); ++f) {
        Vec3 normal{}, centre{};
        const auto& face = faces[f];
        for (std::size_t i = 0; i < face.size(); ++i) {
            const Vec3 a = foam_point(mesh.points, face[i]), b = foam_point(mesh.points, face[(i + 1) % face.size()]);
            normal[0] += (a[1] - b[1]) * (a[2] + b[2]);
            normal[1] += (a[2] - b[2]) * (a[0] + b[0]);
            normal[2] += (a[0] - b[0]) * (a[1] + b[1]);
            for (int d = 0; d < 3; ++d) centre[d] += a[d] / static_cast<double>(face.size());
        }
        const auto side = [&](std::int64_t cell) {
            const Vec3 c = foam_cell_centre(mesh, static_cast<std::size_t>(cell));
            return normal[0] * (centre[0] - c[0]) + normal[1] * (centre[1] - c[1]) + normal[2] * (centre[2] - c[2]);
        };
        ASSERT_GT(side(owner[f]), 0) << "face " << f << " points into its owner";
        if (f < neighbour.size()) {
            ASSERT_LT(side(neighbour[f]), 0) << "face " << f << " points out of its neighbour";
        }
    }
}

/// `read` is `original` as the OpenFOAM writer's documented reordering leaves
/// it: the same points bit for bit; cell i of the same type, bounded by the
/// same faces (as cycles: the same cell with its orientation); the same
/// markers in order, each element of the same type starting at the same node
/// and turned out of the mesh (its nodes in the same cycle or the reverse
/// one); then possibly "defaultFaces".
void expect_same_up_to_foam_order(const Mesh& original, const Mesh& read) {
    ASSERT_EQ(read.points, original.points);
    ASSERT_EQ(read.cells.size(), original.cells.size());
    for (std::size_t c = 0; c < original.cells.size(); ++c) {
        ASSERT_EQ(read.cells.types[c], original.cells.types[c]) << c;
        const auto a = foam_cell_faces(original, c), b = foam_cell_faces(read, c);
        for (const auto& face : a)
            ASSERT_TRUE(std::any_of(b.begin(), b.end(), [&](const auto& g) { return foam_same_cycle(face, g); }))
                << "cell " << c;
    }
    ASSERT_GE(read.markers.size(), original.markers.size());
    ASSERT_LE(read.markers.size(), original.markers.size() + 1);
    if (read.markers.size() > original.markers.size()) {
        EXPECT_EQ(read.markers.back().name, "defaultFaces");
    }
    for (std::size_t m = 0; m < original.markers.size(); ++m) {
        const ElementList& a = original.markers[m].elements;
        const ElementList& b = read.markers[m].elements;
        ASSERT_EQ(read.markers[m].name, original.markers[m].name);
        ASSERT_EQ(a.types, b.types) << original.markers[m].name;
        for (std::size_t e = 0; e < a.size(); ++e) {
            const std::vector<NodeId> x(a.nodes_of(e).begin(), a.nodes_of(e).end());
            const std::vector<NodeId> y(b.nodes_of(e).begin(), b.nodes_of(e).end());
            std::vector<NodeId> reversed(x.rbegin(), x.rend());
            ASSERT_EQ(x[0], y[0]);
            ASSERT_TRUE(foam_same_cycle(x, y) || foam_same_cycle(reversed, y)) << original.markers[m].name << " " << e;
        }
    }
}

std::vector<Mesh> foam_real_3d_meshes() {
    std::vector<Mesh> meshes;
    for (const auto& path : su2_meshes()) {
        Mesh mesh = read_mesh(path);
        if (mesh.dim == 3) meshes.push_back(std::move(mesh));
    }
    return meshes;
}

}  // namespace

TEST(OpenFoamWrite, OpenFoamCasesRoundTripExactly) {
    for (const std::string name : {"cavity", "cavity-binary", "mixed", "mixed-binary"}) {
        OpenFoamSource source;
        const Mesh mesh = read_openfoam(openfoam_case(name), {}, &source);
        for (const foam::Format format : {foam::Format::ascii, foam::Format::binary}) {
            const PolyMeshFiles files = write_openfoam_files(mesh, {format, &source});
            EXPECT_TRUE(read_openfoam_files("written", files) == mesh) << name;
            // The patches keep their types and entries.
            OpenFoamSource again;
            read_openfoam_files("written", files, &again);
            EXPECT_EQ(again.patches, source.patches) << name;
            EXPECT_EQ(again.points_format, format);
        }
    }
}

// What changes when OpenFOAM's own files go through dgwarp: nothing in owner,
// neighbour and the boundary faces (they are already in OpenFOAM's order),
// and the internal faces' first nodes only.
TEST(OpenFoamWrite, OpenFoamsOwnOrderIsKept) {
    for (const std::string name : {"cavity", "mixed"}) {
        OpenFoamSource source;
        const Mesh mesh = read_openfoam(openfoam_case(name), {}, &source);
        const PolyMeshFiles in = openfoam_files(name);
        const PolyMeshFiles out = write_openfoam_files(mesh, {foam::Format::ascii, &source});
        EXPECT_EQ(foam_ascii_labels(out.owner), foam_ascii_labels(in.owner)) << name;
        EXPECT_EQ(foam_ascii_labels(out.neighbour), foam_ascii_labels(in.neighbour)) << name;
        const auto a = foam_ascii_faces(in.faces), b = foam_ascii_faces(out.faces);
        ASSERT_EQ(a.size(), b.size());
        const std::size_t internal = foam_ascii_labels(in.neighbour).size();
        for (std::size_t f = 0; f < a.size(); ++f) {
            if (f < internal) EXPECT_TRUE(foam_same_cycle(a[f], b[f])) << name << " face " << f;
            else EXPECT_EQ(a[f], b[f]) << name << " face " << f;
        }
        expect_openfoam_face_rules(mesh, out);
        // The points as numbers (the text may be shorter: 0.025000000000000001 is written 0.025).
        EXPECT_EQ(foam_body_numbers(out.points), foam_body_numbers(in.points));
    }
}

TEST(OpenFoamWrite, RealSu2MeshesRoundTripUpToTheDocumentedOrder) {
    DGWARP_REQUIRE_SHARED_MESHES();
    const std::vector<Mesh> meshes = foam_real_3d_meshes();
    ASSERT_GE(meshes.size(), 4u);
    for (const Mesh& mesh : meshes) {
        const PolyMeshFiles files = write_openfoam_files(mesh);
        const Mesh read = read_openfoam_files("written", files);
        expect_same_up_to_foam_order(mesh, read);
        expect_openfoam_face_rules(mesh, files);
        // Once in OpenFOAM's order, a round trip changes nothing, in either format.
        for (const foam::Format format : {foam::Format::ascii, foam::Format::binary})
            EXPECT_TRUE(read_openfoam_files("again", write_openfoam_files(read, {format, nullptr})) == read);
    }
}

TEST(OpenFoamWrite, BoundaryFacesInNoMarkerGoToDefaultFaces) {
    Mesh mesh = read_openfoam(openfoam_case("mixed"));
    const Marker top = mesh.markers.back();
    mesh.markers.pop_back();
    const Mesh read = read_openfoam_files("written", write_openfoam_files(mesh));
    ASSERT_EQ(read.markers.size(), 3u);
    EXPECT_EQ(read.markers[2].name, "defaultFaces");
    EXPECT_EQ(read.markers[2].elements.size(), top.elements.size());
    EXPECT_EQ(marker_nodes(read.markers[2]), marker_nodes(top));
}

TEST(OpenFoamWrite, PointsAloneInEitherFormat) {
    const Mesh mesh = read_openfoam(openfoam_case("mixed"));
    std::vector<double> moved = mesh.points;
    for (std::size_t i = 0; i < moved.size(); ++i) moved[i] += 1e-3 * std::sin(static_cast<double>(i));
    const PolyMeshFiles original = openfoam_files("mixed-binary");
    for (const foam::Format format : {foam::Format::ascii, foam::Format::binary}) {
        PolyMeshFiles files = original;
        files.points = openfoam_points_text(moved, format, "0.5/polyMesh");
        EXPECT_NE(files.points.find("location    \"0.5/polyMesh\";"), std::string::npos);
        Mesh expected = mesh;
        expected.points = moved;
        EXPECT_TRUE(read_openfoam_files("moved", files) == expected);
    }
    const auto dir = scratch_dir();
    write_openfoam_points(dir / "case" / "0" / "polyMesh" / "points", moved, foam::Format::binary, "0/polyMesh");
    EXPECT_EQ(slurp(dir / "case" / "0" / "polyMesh" / "points"), openfoam_points_text(moved, foam::Format::binary, "0/polyMesh"));
}

TEST(OpenFoamWrite, CaseFoldersAndCompressedFiles) {
    const auto dir = scratch_dir();
    const Mesh mesh = read_openfoam(openfoam_case("cavity"));
    write_mesh(dir / "new/", mesh);  // a name ending in '/': a case folder
    EXPECT_TRUE(std::filesystem::is_regular_file(dir / "new" / "constant" / "polyMesh" / "faces"));
    write_mesh(dir / "noext", mesh);  // no extension: a case folder
    write_mesh(dir / "other" / "constant" / "polyMesh", mesh);  // a polyMesh folder itself
    for (const char* name : {"new", "noext", "other"}) EXPECT_TRUE(read_mesh(dir / name) == mesh) << name;
    EXPECT_FALSE(std::filesystem::exists(dir / "other" / "constant" / "polyMesh" / "constant"));
    // OpenFOAM's writeCompression: every file gzipped.
    const auto packed = dir / "packed" / "constant" / "polyMesh";
    std::filesystem::create_directories(packed);
    for (const char* file : poly_mesh_file_names)
        std::filesystem::copy_file(dir / "new" / "constant" / "polyMesh" / file, packed / file);
    ASSERT_EQ(run_command("gzip " + quoted(packed) + "/*").exit_code, 0);
    ASSERT_TRUE(std::filesystem::exists(packed / "faces.gz"));
    EXPECT_TRUE(read_mesh(dir / "packed") == mesh);
    // A truncated gzip file.
    const std::string bytes = slurp(packed / "owner.gz");
    write_text(packed / "owner.gz", bytes.substr(0, bytes.size() / 2));
    EXPECT_THROW(read_mesh(dir / "packed"), ParseError);
}

TEST(OpenFoamWrite, MeshesAPolyMeshCannotHoldAreRefusedBeforeWriting) {
    const Mesh mixed = read_openfoam(openfoam_case("mixed"));
    const auto refused = [](const Mesh& mesh, const std::string& text) {
        try {
            write_openfoam_files(mesh);
            ADD_FAILURE() << "no error: " << text;
        } catch (const MeshError& e) {
            EXPECT_NE(std::string(e.what()).find(text), std::string::npos) << e.what();
        }
    };
    Mesh flat;
    flat.dim = 2;
    flat.points = {0, 0, 1, 0, 0, 1};
    flat.cells.push_back(CellType::triangle, std::vector<NodeId>{0, 1, 2});
    refused(flat, "OpenFOAM meshes are 3D");
    // A marker holding an inner face: the first face written is one.
    const std::vector<NodeId> face = foam_ascii_faces(write_openfoam_files(mixed).faces).at(0);
    Mesh probe = mixed;
    probe.markers.push_back({"probe", {}});
    probe.markers.back().elements.push_back(face.size() == 3 ? CellType::triangle : CellType::quadrilateral, face);
    refused(probe, "marker 'probe' element 0 (nodes " + std::to_string(face[0]));
    refused(probe, "is not a boundary face of the cells");
    // The same face in two markers.
    Mesh twice = mixed;
    twice.markers.push_back(twice.markers[0]);
    twice.markers.back().name = "copy";
    refused(twice, "is also in marker 'bottom'");
    // A cell turned inside out beside valid ones.
    Mesh flipped = mixed;
    const auto tet = static_cast<std::size_t>(
        std::find(flipped.cells.types.begin(), flipped.cells.types.end(), CellType::tetrahedron) - flipped.cells.types.begin());
    auto& nodes = flipped.cells.nodes;
    const auto at = static_cast<std::size_t>(flipped.cells.offsets[tet]);
    std::swap(nodes[at + 1], nodes[at + 2]);
    refused(flipped, "with the same orientation: one of them is inverted");
    // A marker name that is not one word.
    Mesh named = mixed;
    named.markers[0].name = "two words";
    refused(named, "cannot name an OpenFOAM patch");
}

TEST(OpenFoamWrite, RefusesCountsItsThirtyTwoBitLabelsCannotHold) {
    // owner/neighbour hold cell numbers and a binary faces file the offsets
    // of its faceCompactList, all 32-bit: the writer narrowed them unchecked.
    constexpr std::int64_t most = 2147483647;
    EXPECT_NO_THROW(foam::check_label_size(most, most));
    for (const auto& [cells, entries, what] :
         {std::tuple{most + 1, std::int64_t{8}, "2147483648 cells"},
          std::tuple{std::int64_t{8}, most + 1, "2147483648 face-node entries"}}) {
        try {
            foam::check_label_size(cells, entries);
            FAIL() << "no error for " << what;
        } catch (const MeshError& e) {
            EXPECT_NE(std::string(e.what()).find(what), std::string::npos) << e.what();
            EXPECT_NE(std::string(e.what()).find("32-bit"), std::string::npos) << e.what();
        }
    }
}


TEST(OpenFoamWrite, PolyhedraRoundTripExactly) {
    // snappyHexMesh's sphere in a box and polyDualMesh's cavity: a polyhedron
    // depends only on its faces as cycles (each from its smallest node, the
    // faces sorted), so the faces written anew read back the same cells.
    for (const std::string name : {"snappy-sphere", "cavity-polyhedral"}) {
        OpenFoamSource source;
        const Mesh mesh = read_openfoam(openfoam_case(name), {}, &source);
        for (const foam::Format format : {foam::Format::ascii, foam::Format::binary})
            EXPECT_TRUE(read_openfoam_files("written", write_openfoam_files(mesh, {format, &source})) == mesh) << name;
    }
}
