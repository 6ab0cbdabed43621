// The example motion files (examples/motions) parse, and resolve on the real
// SU2 meshes they were written for: airfoil_* on SU2's NACA0012 mesh,
// brick_prism_*, brick_pyra_*, brick_tets_* on its prism, pyramid and
// tetrahedral bricks, the other brick_* on its hexahedral brick (all the box
// [0,2]×[0,1]×[0,1], markers x_m … z_p); openfoam_mixed_* on the OpenFOAM case
// tests/data/openfoam/mixed.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>

#include "dgwarp/core/error.hpp"
#include "dgwarp/io/mesh_io.hpp"
#include "dgwarp/io/motion_file.hpp"
#include "dgwarp/motion/resolve_motion.hpp"
#include "support/test_paths.hpp"

using namespace dgwarp;

namespace {

std::filesystem::path examples_dir() { return test::source_dir() / "examples" / "motions"; }

std::vector<std::filesystem::path> example_files() {
    std::vector<std::filesystem::path> files;
    for (const auto& e : std::filesystem::directory_iterator(examples_dir()))
        if (e.path().extension() == ".json") files.push_back(e.path());
    std::sort(files.begin(), files.end());
    return files;
}

/// The real SU2 mesh `name` (tests call DGWARP_REQUIRE_SHARED_MESHES first:
/// a reader error fails the test).
Mesh load_mesh(const std::string& name) { return read_mesh(test::su2_meshes_dir() / name); }

const std::string naca0012 = "deformation_naca0012_mesh_NACA0012_inv.su2";
const std::string brick = "deformation_brick_hex_mesh_brick_hex_ffd.su2";
const std::vector<std::string> brick_kinds = {"hex", "prism", "pyra", "tets"};

std::string brick_mesh(const std::string& kind) {
    return "deformation_brick_" + kind + "_mesh_brick_" + kind + "_ffd.su2";
}

const std::string openfoam_mixed = "tests/data/openfoam/mixed";

/// The mesh an example file is for (see the file comment).
std::string mesh_of_example(const std::string& file_name) {
    if (file_name.rfind("openfoam_mixed", 0) == 0) return openfoam_mixed;
    if (file_name.rfind("airfoil", 0) == 0) return naca0012;
    for (const std::string& kind : brick_kinds)
        if (file_name.rfind("brick_" + kind + "_", 0) == 0) return brick_mesh(kind);
    return brick;
}

std::vector<NodeId> union_of_markers(const Mesh& mesh) {
    std::vector<NodeId> all;
    for (const Marker& m : mesh.markers) {
        const auto n = marker_nodes(m);
        all.insert(all.end(), n.begin(), n.end());
    }
    std::sort(all.begin(), all.end());
    all.erase(std::unique(all.begin(), all.end()), all.end());
    return all;
}

}  // namespace

TEST(MotionExamples, EveryExampleParses) {
    const auto files = example_files();
    ASSERT_GE(files.size(), 10u);
    for (const auto& f : files) {
        SCOPED_TRACE(f.filename().string());
        const MotionSpec spec = read_motion_file(f);
        EXPECT_GE(frame_count(spec), 1u);
    }
}

TEST(MotionExamples, EveryExampleResolvesOnItsMesh) {
    DGWARP_REQUIRE_SHARED_MESHES();
    std::map<std::string, Mesh> meshes;
    for (const std::string& name : {naca0012, brick_mesh("hex"), brick_mesh("prism"), brick_mesh("pyra"), brick_mesh("tets")})
        meshes.emplace(name, load_mesh(name));
    meshes.emplace(openfoam_mixed, read_mesh(test::source_dir() / openfoam_mixed));
    for (const auto& f : example_files()) {
        SCOPED_TRACE(f.filename().string());
        const Mesh& mesh = meshes.at(mesh_of_example(f.filename().string()));
        const MotionSpec spec = read_motion_file(f);
        const ResolvedBoundary rb = resolve_boundary(mesh, spec);
        EXPECT_EQ(rb.boundary.nodes, union_of_markers(mesh));
        for (std::size_t k = 0; k < frame_count(spec); ++k) {
            const ResolvedFrame fr = resolve_frame(mesh, spec, rb, k);
            ASSERT_EQ(fr.motion.size(), rb.boundary.nodes.size());
            for (std::size_t b = 0; b < fr.motion.size(); ++b) {
                if (!rb.boundary.moving[b]) {
                    EXPECT_EQ(fr.motion[b], NodeMotion{});
                }
            }
        }
    }
}

TEST(MotionExamples, RotatedAirfoilStaysRigid) {
    DGWARP_REQUIRE_SHARED_MESHES();
    const Mesh mesh = load_mesh(naca0012);
    const MotionSpec spec = read_motion_file(examples_dir() / "airfoil_rotate.json");
    const ResolvedBoundary rb = resolve_boundary(mesh, spec);
    const auto airfoil = marker_nodes(find_marker(mesh, "airfoil"));
    EXPECT_EQ(std::count(rb.boundary.moving.begin(), rb.boundary.moving.end(), 1),
              static_cast<std::ptrdiff_t>(airfoil.size()));
    const auto p = moved_boundary_points(mesh, rb.boundary, resolve_frame(mesh, spec, rb, 0).motion);
    // Distances between moved airfoil nodes equal the original ones.
    std::vector<std::size_t> slots;
    for (NodeId n : airfoil)
        slots.push_back(static_cast<std::size_t>(
            std::lower_bound(rb.boundary.nodes.begin(), rb.boundary.nodes.end(), n) - rb.boundary.nodes.begin()));
    for (std::size_t i = 0; i + 7 < airfoil.size(); i += 7) {
        const auto a = static_cast<std::size_t>(airfoil[i]), b = static_cast<std::size_t>(airfoil[i + 7]);
        const double d0 = std::hypot(mesh.points[2 * a] - mesh.points[2 * b], mesh.points[2 * a + 1] - mesh.points[2 * b + 1]);
        const double d1 = std::hypot(p[2 * slots[i]] - p[2 * slots[i + 7]], p[2 * slots[i] + 1] - p[2 * slots[i + 7] + 1]);
        EXPECT_NEAR(d0, d1, 1e-14);
    }
}

// The 3D acceptance case: z_p turns 10° in its plane; under moving_wins its
// edges, shared with the fixed side faces, turn with it (docs/MOTION.md).
TEST(MotionExamples, BrickTopRotationTurnsTheSharedEdgesWithTheTop) {
    DGWARP_REQUIRE_SHARED_MESHES();
    const Mesh mesh = load_mesh(brick);
    const MotionSpec spec = read_motion_file(examples_dir() / "brick_rotate_top.json");
    EXPECT_EQ(spec.shared_nodes, SharedNodeRule::moving_wins);
    const ResolvedBoundary rb = resolve_boundary(mesh, spec);
    const auto top = marker_nodes(find_marker(mesh, "z_p"));
    std::vector<NodeId> sides;
    for (const char* name : {"x_m", "x_p", "y_m", "y_p"}) {
        const auto n = marker_nodes(find_marker(mesh, name));
        sides.insert(sides.end(), n.begin(), n.end());
    }
    std::sort(sides.begin(), sides.end());
    const auto fr = resolve_frame(mesh, spec, rb, 0);
    const auto p = moved_boundary_points(mesh, rb.boundary, fr.motion);
    std::size_t moving = 0, shared = 0;
    for (std::size_t b = 0; b < rb.boundary.nodes.size(); ++b) {
        const NodeId n = rb.boundary.nodes[b];
        const bool on_top = std::binary_search(top.begin(), top.end(), n);
        EXPECT_EQ(rb.boundary.moving[b], on_top) << "node " << n;
        if (!rb.boundary.moving[b]) continue;
        ++moving;
        shared += std::binary_search(sides.begin(), sides.end(), n);
        EXPECT_NEAR(fr.motion[b].rotation[2], 10 * std::numbers::pi / 180, 1e-15);
        EXPECT_NEAR(p[3 * b + 2], 1.0, 1e-12);  // stays in the plane z = 1
        // and at the same distance from the centre (1, 0.5).
        const auto x = mesh.points.data() + 3 * static_cast<std::size_t>(n);
        EXPECT_NEAR(std::hypot(p[3 * b] - 1, p[3 * b + 1] - 0.5), std::hypot(x[0] - 1, x[1] - 0.5), 1e-14);
    }
    EXPECT_EQ(moving, top.size());
    EXPECT_EQ(shared, 2u * (40 + 20) - 4);  // the rim of the 40 × 20 top face
}

// The bump files hold dz = 0.1 sin(πx/2) sin(πy) at the coordinates dgwarp reads
// for their node ids, on every brick mesh.
TEST(MotionExamples, BrickBumpFilesMatchTheirMeshes) {
    DGWARP_REQUIRE_SHARED_MESHES();
    for (const std::string& kind : brick_kinds) {
        SCOPED_TRACE(kind);
        const Mesh mesh = load_mesh(brick_mesh(kind));
        const std::string file = kind == "hex" ? "brick_bump_top.json" : "brick_" + kind + "_bump_top.json";
        const MotionSpec spec = read_motion_file(examples_dir() / file);
        const auto& table = std::get<PrescribedDisplacements>(spec.frames.at(0).markers.at("z_p")).displacements;
        EXPECT_EQ(table.nodes.size(), marker_nodes(find_marker(mesh, "z_p")).size());
        for (std::size_t i = 0; i < table.nodes.size(); ++i) {
            const double* x = mesh.points.data() + 3 * static_cast<std::size_t>(table.nodes[i]);
            EXPECT_NEAR(x[2], 1.0, 1e-15) << "node " << table.nodes[i];
            const double dz = 0.1 * std::sin(std::numbers::pi * x[0] / 2) * std::sin(std::numbers::pi * x[1]);
            EXPECT_NEAR(table.values[i][2], dz, 1e-14) << "node " << table.nodes[i];
            EXPECT_EQ(table.values[i][0], 0.0);
            EXPECT_EQ(table.values[i][1], 0.0);
        }
    }
}
