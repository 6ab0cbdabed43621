#include "dgwarp/motion/resolve_motion.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <algorithm>
#include <fstream>
#include <iterator>
#include <numbers>

#include "dgwarp/core/error.hpp"
#include "dgwarp/io/mesh_io.hpp"
#include "dgwarp/io/motion_file.hpp"
#include "motion/motion_test_meshes.hpp"
#include "support/degrees.hpp"
#include "support/test_paths.hpp"

using namespace dgwarp;
using dgwarp::test::chain;
using dgwarp::test::cube_faces;
using dgwarp::test::two_squares;
using dgwarp::test::deg;

namespace {

/// Parses a motion file whose relative file names are looked up in `dir`.
MotionSpec spec_in(const std::filesystem::path& dir, const std::string& json) {
    return parse_motion_file(json, "m.json", dir);
}
MotionSpec spec_of(const std::string& json) { return parse_motion_file(json, "m.json", "."); }

/// The motion of mesh node `node` in `motion` (which follows `boundary`).
const NodeMotion& motion_of(const BoundarySet& boundary, const BoundaryMotion& motion, NodeId node) {
    const auto it = std::lower_bound(boundary.nodes.begin(), boundary.nodes.end(), node);
    EXPECT_TRUE(it != boundary.nodes.end() && *it == node) << "node " << node << " not in the boundary set";
    return motion[static_cast<std::size_t>(it - boundary.nodes.begin())];
}

/// The MeshError that f() throws, or fails the test.
template <class F>
MeshError mesh_error_of(F f) {
    try {
        f();
    } catch (const MeshError& e) {
        return e;
    }
    ADD_FAILURE() << "no MeshError";
    return MeshError("");
}

bool contains(const std::string& s, const std::string& part) { return s.find(part) != std::string::npos; }

void write(const std::filesystem::path& path, const std::string& text) { std::ofstream(path) << text; }

}  // namespace

TEST(MotionResolve, IssueExampleOnTwoSquares) {
    const Mesh mesh = two_squares();
    const MotionSpec spec = spec_of(R"({"markers": {"airfoil": {"rotate": {"angle_deg": 45, "axis": [0, 0, 1], "center": [0.25, 0, 0]},
                                                                "translate": [0, 0, 0]},
                                                    "farfield": "fixed"}})");
    const ResolvedBoundary rb = resolve_boundary(mesh, spec);
    EXPECT_EQ(rb.boundary.nodes, (std::vector<NodeId>{0, 1, 2, 3, 4, 5, 6, 7}));  // not the volume node 8
    EXPECT_EQ(rb.boundary.moving, (std::vector<std::uint8_t>{0, 0, 0, 0, 1, 1, 1, 1}));
    EXPECT_EQ(rb.moving_markers, (std::vector<std::string>{"airfoil"}));
    EXPECT_EQ(rb.static_markers, (std::vector<std::string>{"farfield"}));
    EXPECT_TRUE(rb.warnings.empty());

    ASSERT_EQ(frame_count(spec), 1u);
    const ResolvedFrame f = resolve_frame(mesh, spec, rb, 0);
    EXPECT_TRUE(f.warnings.empty());
    const NodeMotion expected{{0, 0, 0}, {0, 0, std::numbers::pi / 4}, {0.25, 0, 0}};
    for (NodeId n = 0; n < 8; ++n) EXPECT_EQ(motion_of(rb.boundary, f.motion, n), n < 4 ? NodeMotion{} : expected);

    // New positions, by hand: node 4 (-0.5, -0.5) is (-0.75, -0.5) from the centre; rotated by 45°
    // it is 0.25 + (-0.75 + 0.5)/√2 = 0.0732233, (-0.75 - 0.5)/√2 = -0.8838835.
    const auto p = moved_boundary_points(mesh, rb.boundary, f.motion);
    ASSERT_EQ(p.size(), 16u);
    EXPECT_NEAR(p[8], 0.0732233, 1e-7);
    EXPECT_NEAR(p[9], -0.8838835, 1e-7);
    EXPECT_NEAR(p[10], 0.7803301, 1e-7);  // node 5: 0.25 + 0.75/√2
    EXPECT_NEAR(p[11], -0.1767767, 1e-7);  //          -0.25/√2
    EXPECT_EQ(p[0], -2);                   // farfield stays
    EXPECT_EQ(p[1], -2);
    // Rigid: the airfoil's side lengths stay 1.
    EXPECT_NEAR(std::hypot(p[10] - p[8], p[11] - p[9]), 1.0, 1e-14);
}

TEST(MotionResolve, MarkersNotNamedAreFixedUnlessADefaultMovesThem) {
    const Mesh mesh = chain();
    const MotionSpec spec = spec_of(R"({"markers": {"a": {"translate": [0, 1]}}})");
    const ResolvedBoundary rb = resolve_boundary(mesh, spec);
    EXPECT_EQ(rb.moving_markers, (std::vector<std::string>{"a"}));
    EXPECT_EQ(rb.static_markers, (std::vector<std::string>{"b", "wall"}));
    // a's nodes 0-2 move (1 and 2 are on b too: moving_wins), the rest stays.
    EXPECT_EQ(rb.boundary.moving, (std::vector<std::uint8_t>{1, 1, 1, 0, 0, 0}));
    const auto f = resolve_frame(mesh, spec, rb, 0);
    EXPECT_EQ(motion_of(rb.boundary, f.motion, 2).translation, (Vec3{0, 1, 0}));
    EXPECT_EQ(motion_of(rb.boundary, f.motion, 3), NodeMotion{});

    const MotionSpec moved = spec_of(R"({"markers": {"wall": "fixed"}, "default": {"translate": [0, 1]}})");
    const ResolvedBoundary rd = resolve_boundary(mesh, moved);
    EXPECT_EQ(rd.moving_markers, (std::vector<std::string>{"a", "b"}));
    EXPECT_EQ(rd.boundary.moving, (std::vector<std::uint8_t>{1, 1, 1, 1, 0, 0}));
}

TEST(MotionResolve, UnknownMarkerNamesItAndListsTheMeshMarkers) {
    const MeshError e = mesh_error_of([] { resolve_boundary(two_squares(), spec_of(R"({"markers": {"wing": "fixed"}})")); });
    EXPECT_EQ(e.marker(), "wing");
    EXPECT_TRUE(contains(e.what(), "airfoil, farfield")) << e.what();
    EXPECT_TRUE(contains(e.what(), "m.json")) << e.what();
    const MeshError f = mesh_error_of([] {
        resolve_boundary(two_squares(), spec_of(R"({"frames": [{"markers": {}}, {"markers": {"wng": "fixed"}}]})"));
    });
    EXPECT_EQ(f.marker(), "wng");
    EXPECT_TRUE(contains(f.what(), "frame 1")) << f.what();
}

TEST(MotionResolve, CheckMarkerNamesAloneRefusesWhatResolveBoundaryRefuses) {
    EXPECT_NO_THROW(check_marker_names(two_squares(), spec_of(R"({"markers": {"airfoil": "fixed"}})")));
    const MeshError e = mesh_error_of([] { check_marker_names(two_squares(), spec_of(R"({"markers": {"wing": "fixed"}})")); });
    EXPECT_EQ(e.marker(), "wing");
    EXPECT_TRUE(contains(e.what(), "airfoil, farfield")) << e.what();
}

TEST(MotionResolve, DisplacementFileGivesTranslationPerNode) {
    const auto dir = test::scratch_dir();
    write(dir / "d.csv", "node,dx,dy\n4,0.1,0\n5,0.2,0\n6,0.3,-0.1\n7,0,0\n");
    const Mesh mesh = two_squares();
    const MotionSpec spec = spec_in(dir, R"({"markers": {"airfoil": {"displacement_file": "d.csv"}}})");
    const ResolvedBoundary rb = resolve_boundary(mesh, spec);
    // Node 7's displacement is zero, but it is on a moving marker: it counts as moving.
    EXPECT_EQ(rb.boundary.moving, (std::vector<std::uint8_t>{0, 0, 0, 0, 1, 1, 1, 1}));
    const auto f = resolve_frame(mesh, spec, rb, 0);
    EXPECT_EQ(motion_of(rb.boundary, f.motion, 6), (NodeMotion{{0.3, -0.1, 0}, {}, {}}));
    EXPECT_EQ(motion_of(rb.boundary, f.motion, 7), NodeMotion{});
    const auto p = moved_boundary_points(mesh, rb.boundary, f.motion);
    EXPECT_DOUBLE_EQ(p[12], 0.8);  // node 6: (0.5, 0.5) + (0.3, -0.1)
    EXPECT_DOUBLE_EQ(p[13], 0.4);
}

TEST(MotionResolve, DisplacementFileMustCoverExactlyItsMarker) {
    const auto dir = test::scratch_dir();
    const Mesh mesh = two_squares();
    const auto resolve = [&](const std::string& csv) {
        write(dir / "d.csv", csv);
        resolve_boundary(mesh, spec_in(dir, R"({"markers": {"airfoil": {"displacement_file": "d.csv"}}})"));
    };
    // Missing nodes: the first one and the count.
    MeshError missing = mesh_error_of([&] { resolve("4,0,0\n6,0,0\n"); });
    EXPECT_EQ(missing.marker(), "airfoil");
    EXPECT_EQ(missing.index(), 5);
    EXPECT_TRUE(contains(missing.what(), "2 of the 4 nodes")) << missing.what();
    EXPECT_TRUE(contains(missing.what(), "first: node 5")) << missing.what();
    // One missing node: "1 of the 4 nodes ... is not in" (issue #27, item 16: "are not", "first").
    MeshError one = mesh_error_of([&] { resolve("4,0,0\n6,0,0\n7,0,0\n"); });
    EXPECT_TRUE(contains(one.what(), "1 of the 4 nodes of marker 'airfoil' is not in")) << one.what();
    EXPECT_TRUE(contains(one.what(), "(node 5)")) << one.what();
    // A mesh node that is not on the marker (the farfield's node 2), with its line.
    MeshError off = mesh_error_of([&] { resolve("4,0,0\n5,0,0\n6,0,0\n7,0,0\n2,1,1\n"); });
    EXPECT_EQ(off.index(), 2);
    EXPECT_TRUE(contains(off.what(), "not on marker 'airfoil'")) << off.what();
    EXPECT_TRUE(contains(off.what(), "d.csv (line 5)")) << off.what();
    // Not a node of the mesh at all.
    MeshError out = mesh_error_of([&] { resolve("4,0,0\n5,0,0\n6,0,0\n7,0,0\n9,1,1\n"); });
    EXPECT_EQ(out.index(), 9);
    EXPECT_TRUE(contains(out.what(), "not a node of the mesh, which has 9 nodes")) << out.what();
    // A z displacement in a 2D mesh.
    MeshError planar = mesh_error_of([&] { resolve("4,0,0,0\n5,0,0,0.5\n6,0,0,0\n7,0,0,0\n"); });
    EXPECT_EQ(planar.index(), 5);
    EXPECT_TRUE(contains(planar.what(), "2D")) << planar.what();
    // 3 components with z = 0 are fine in 2D.
    EXPECT_NO_THROW(resolve("4,0,0,0\n5,0,0,0\n6,0,0,0\n7,0,0,0\n"));
}

TEST(MotionResolve, TwoComponentFileOnA3DMeshIsAnError) {
    const auto dir = test::scratch_dir();
    write(dir / "d.csv", "4,0,0\n5,0,0\n6,0,0\n7,0,0\n");
    const MeshError e = mesh_error_of(
        [&] { resolve_boundary(cube_faces(), spec_in(dir, R"({"markers": {"top": {"displacement_file": "d.csv"}}})")); });
    EXPECT_EQ(e.marker(), "top");
    EXPECT_TRUE(contains(e.what(), "2 coordinates per node, but the mesh is 3D")) << e.what();
}

TEST(MotionResolve, Su2SurfaceFileSharedByTwoMarkersGivesNewPositions) {
    const auto dir = test::scratch_dir();
    // SU2 writes each marker's nodes, so the shared nodes 1 and 2 appear twice.
    write(dir / "surface_positions.dat", "0\t0\t0.5\n1\t1\t0.5\n2\t2\t0.5\n1\t1\t0.5\n2\t2\t0.5\n3\t3.25\t0.5\n");
    const Mesh mesh = chain();
    const MotionSpec spec = spec_in(dir, R"({"markers": {"a": {"surface_file": "surface_positions.dat"},
                                                         "b": {"surface_file": "surface_positions.dat"}}})");
    const ResolvedBoundary rb = resolve_boundary(mesh, spec);
    EXPECT_EQ(rb.boundary.moving, (std::vector<std::uint8_t>{1, 1, 1, 1, 0, 0}));
    const auto f = resolve_frame(mesh, spec, rb, 0);
    EXPECT_EQ(motion_of(rb.boundary, f.motion, 3).translation, (Vec3{0.25, 0.5, 0}));
    const auto p = moved_boundary_points(mesh, rb.boundary, f.motion);
    for (std::size_t n = 0; n < 3; ++n) {
        EXPECT_EQ(p[2 * n], static_cast<double>(n));
        EXPECT_EQ(p[2 * n + 1], 0.5);
    }
    // The same file for a alone names nodes that are not on a.
    const MeshError e = mesh_error_of(
        [&] { resolve_boundary(mesh, spec_in(dir, R"({"markers": {"a": {"surface_file": "surface_positions.dat"}}})")); });
    EXPECT_EQ(e.index(), 3);
    EXPECT_TRUE(contains(e.what(), "not on marker 'a'")) << e.what();
}

TEST(MotionResolve, NodeMotionFileTwistsIn3D) {
    // A twist of the top face about the vertical line through (0.5, 0.5): each node turns by an
    // angle proportional to its x (0 at x = 0, 90° at x = 1).
    const auto dir = test::scratch_dir();
    write(dir / "twist.csv",
          "node,tx,ty,tz,wx,wy,wz,cx,cy,cz\n"
          "4,0,0,0,0,0,0,0.5,0.5,1\n"
          "5,0,0,0,0,0,1.5707963267948966,0.5,0.5,1\n"
          "6,0,0,0,0,0,0,0.5,0.5,1\n"
          "7,0,0,0.1,0,0,1.5707963267948966,0.5,0.5,1\n");
    const Mesh mesh = cube_faces();
    const MotionSpec spec = spec_in(dir, R"({"markers": {"top": {"node_motion_file": "twist.csv"}}})");
    const ResolvedBoundary rb = resolve_boundary(mesh, spec);
    EXPECT_EQ(rb.boundary.nodes.size(), 8u);
    const auto f = resolve_frame(mesh, spec, rb, 0);
    const auto p = moved_boundary_points(mesh, rb.boundary, f.motion);
    // Node 5 (1, 0, 1) turns 90° about (0.5, 0.5): (0.5, -0.5) -> (0.5, 0.5) from the centre.
    EXPECT_NEAR(p[15], 1.0, 1e-15);
    EXPECT_NEAR(p[16], 1.0, 1e-15);
    EXPECT_NEAR(p[17], 1.0, 1e-15);
    // Node 7 (1, 1, 1): (0.5, 0.5) -> (-0.5, 0.5), then up by 0.1.
    EXPECT_NEAR(p[21], 0.0, 1e-15);
    EXPECT_NEAR(p[22], 1.0, 1e-15);
    EXPECT_NEAR(p[23], 1.1, 1e-15);
    // Nodes 4 and 6 are also on "side" (static); moving_wins: they follow top, with zero motion.
    EXPECT_EQ(rb.boundary.moving[4], 1);
    EXPECT_EQ(rb.boundary.moving[6], 1);
    ASSERT_EQ(rb.warnings.size(), 1u);
    EXPECT_TRUE(contains(rb.warnings[0].text, "2 boundary nodes are on both a moving and a static marker"))
        << rb.warnings[0].text;
    EXPECT_EQ(rb.warnings[0].code, WarningCode::shared_moving_static);
    EXPECT_EQ(rb.warnings[0].count, 2);
}

TEST(MotionResolve, FramesListGivesOneMotionPerFrame) {
    const Mesh mesh = chain();
    const MotionSpec spec = spec_of(R"({"frames": [{"markers": {"wall": {"translate": [1, 0]}}},
                                                   {"markers": {"wall": "fixed"}},
                                                   {"markers": {"wall": {"rotate": {"angle_deg": 90, "center": [3, 0]}}}}]})");
    const ResolvedBoundary rb = resolve_boundary(mesh, spec);
    // wall moves in some frame: its nodes are moving in every frame.
    EXPECT_EQ(rb.boundary.moving, (std::vector<std::uint8_t>{0, 0, 0, 1, 1, 1}));
    ASSERT_EQ(frame_count(spec), 3u);
    EXPECT_EQ(motion_of(rb.boundary, resolve_frame(mesh, spec, rb, 0).motion, 5).translation, (Vec3{1, 0, 0}));
    EXPECT_EQ(motion_of(rb.boundary, resolve_frame(mesh, spec, rb, 1).motion, 5), NodeMotion{});
    const auto f2 = resolve_frame(mesh, spec, rb, 2);
    const auto p = moved_boundary_points(mesh, rb.boundary, f2.motion);
    EXPECT_NEAR(p[10], 3.0, 1e-15);  // node 5 (5, 0) turns 90° about (3, 0) to (3, 2)
    EXPECT_NEAR(p[11], 2.0, 1e-15);
    EXPECT_EQ(p[6], 3.0);  // node 3, the centre, stays
}

TEST(MotionResolve, PeriodicPitchPlungeAtStepsComputedByHand) {
    const Mesh mesh = two_squares();
    const MotionSpec spec = spec_of(R"({"markers": {"airfoil": {"periodic": {
        "pitch": {"amplitude_deg": 10, "frequency": 2, "phase_deg": 30, "center": [0, 0]},
        "plunge": {"amplitude": [0, 0.5], "frequency": 1, "phase_deg": 90}}}},
      "time": {"time_step": 0.1, "steps": 4}})");
    const ResolvedBoundary rb = resolve_boundary(mesh, spec);
    ASSERT_EQ(frame_count(spec), 4u);
    // t_k = 0.1 k: angle = 10° sin(72° k + 30°), plunge = 0.5 sin(36° k + 90°).
    // k = 0: 5°, 0.5; k = 1: 9.781476°, 0.4045085; k = 3: 10° sin 246° = -9.135455°, 0.5 sin 198° = -0.1545085.
    const double angle[] = {5.0, 9.781476, 0, -9.135455}, plunge[] = {0.5, 0.4045085, 0, -0.1545085};
    for (std::size_t k : {0u, 1u, 3u}) {
        const auto f = resolve_frame(mesh, spec, rb, k);
        const NodeMotion& m = motion_of(rb.boundary, f.motion, 6);
        EXPECT_NEAR(m.rotation[2], angle[k] * deg, 1e-8) << k;
        EXPECT_NEAR(m.translation[1], plunge[k], 1e-7) << k;
        EXPECT_EQ(motion_of(rb.boundary, f.motion, 0), NodeMotion{});
    }
}

TEST(MotionResolve, AgreeingMovingMarkersShareNodes) {
    const Mesh mesh = chain();
    // Same motion on a and b.
    const MotionSpec same = spec_of(R"({"markers": {"a": {"translate": [0, 1]}, "b": {"translate": [0, 1]}}})");
    const ResolvedBoundary rb = resolve_boundary(mesh, same);
    const auto f = resolve_frame(mesh, same, rb, 0);
    EXPECT_EQ(motion_of(rb.boundary, f.motion, 2).translation, (Vec3{0, 1, 0}));

    // a turns 90° about node 2 = (2, 0), which moves node 1 to (2, -1) and leaves node 2; b translates
    // by (1, -1), which moves node 1 there too but node 2 to (3, -1): they disagree on node 2 alone.
    const MotionSpec partly = spec_of(R"({"markers": {"a": {"rotate": {"angle_deg": 90, "center": [2, 0]}},
                                                      "b": {"translate": [1, -1]}}})");
    const MeshError e = mesh_error_of([&] { resolve_boundary(mesh, partly); });
    EXPECT_TRUE(contains(e.what(), "'a' and 'b' on 1 node")) << e.what();
    EXPECT_EQ(e.index(), 2);

    // Different NodeMotions, same new positions: a's centre differs from b's, but with a zero angle
    // both only translate by (0, 1).
    const MotionSpec by_position = spec_of(R"({"markers": {"a": {"rotate": {"angle_deg": 0, "center": [7, 7]}, "translate": [0, 1]},
                                                           "b": {"translate": [0, 1]}}})");
    const ResolvedBoundary rp = resolve_boundary(mesh, by_position);
    const auto fp = resolve_frame(mesh, by_position, rp, 0);
    // Node 2 takes the motion of a, the first of its markers in mesh order.
    EXPECT_EQ(motion_of(rp.boundary, fp.motion, 2).center, (Vec3{7, 7, 0}));
    EXPECT_EQ(motion_of(rp.boundary, fp.motion, 3).center, (Vec3{0, 0, 0}));
}

TEST(MotionResolve, DisagreeingMovingMarkersNameTheMarkersAndCount) {
    const Mesh mesh = chain();
    const MotionSpec spec = spec_of(R"({"markers": {"a": {"translate": [1, 0]}, "b": {"translate": [0, 1]}}})");
    const MeshError e = mesh_error_of([&] { resolve_boundary(mesh, spec); });
    EXPECT_TRUE(contains(e.what(), "markers 'a' and 'b' on 2 nodes")) << e.what();
    EXPECT_EQ(e.marker(), "a");
    EXPECT_EQ(e.index(), 1);
    // static_wins does not help nodes that are on moving markers only.
    const MotionSpec st = spec_of(R"({"markers": {"a": {"translate": [1, 0]}, "b": {"translate": [0, 1]}},
                                      "shared_nodes": "static_wins"})");
    EXPECT_THROW(resolve_boundary(mesh, st), MeshError);
}

TEST(MotionResolve, ConflictInALaterFrameNamesTheFrame) {
    const Mesh mesh = chain();
    const MotionSpec spec = spec_of(R"({"frames": [{"markers": {"a": {"translate": [1, 0]}, "b": {"translate": [1, 0]}}},
                                                   {"markers": {"a": {"translate": [1, 0]}, "b": {"translate": [2, 0]}}}]})");
    const MeshError e = mesh_error_of([&] { resolve_boundary(mesh, spec); });
    EXPECT_TRUE(contains(e.what(), "frame 1")) << e.what();
}

TEST(MotionResolve, PositionsWithinTheToleranceAgree) {
    const Mesh mesh = chain();  // bounding-box diagonal 5: default tolerance 5e-9
    const MotionSpec close = spec_of(R"({"markers": {"a": {"translate": [1, 0]}, "b": {"translate": [1.000000001, 0]}}})");
    EXPECT_NO_THROW(resolve_boundary(mesh, close));
    const MotionSpec far = spec_of(R"({"markers": {"a": {"translate": [1, 0]}, "b": {"translate": [1.001, 0]}}})");
    EXPECT_THROW(resolve_boundary(mesh, far), MeshError);
    const MotionSpec loose = spec_of(R"({"markers": {"a": {"translate": [1, 0]}, "b": {"translate": [1.001, 0]}},
                                         "shared_tolerance": 0.01})");
    EXPECT_NO_THROW(resolve_boundary(mesh, loose));
}

TEST(MotionResolve, MovingAndStaticMarkerRules) {
    const Mesh mesh = cube_faces();
    // Rotate the top face about its centre; the side (x = 0) shares nodes 4 and 6 with it.
    const std::string motion = R"("top": {"rotate": {"angle_deg": 10, "axis": [0, 0, 1], "center": [0.5, 0.5, 1]}})";
    const MotionSpec moving = spec_of(R"({"markers": {)" + motion + "}}");
    const ResolvedBoundary rm = resolve_boundary(mesh, moving);
    EXPECT_EQ(rm.boundary.moving, (std::vector<std::uint8_t>{0, 0, 0, 0, 1, 1, 1, 1}));
    EXPECT_TRUE(contains(rm.warnings.at(0).text, "follow the moving markers")) << rm.warnings[0].text;
    const auto fm = resolve_frame(mesh, moving, rm, 0);
    EXPECT_NEAR(motion_of(rm.boundary, fm.motion, 4).rotation[2], 10 * deg, 1e-15);

    const MotionSpec fixed_edges = spec_of(R"({"markers": {)" + motion + R"(}, "shared_nodes": "static_wins"})");
    const ResolvedBoundary rs = resolve_boundary(mesh, fixed_edges);
    EXPECT_EQ(rs.boundary.moving, (std::vector<std::uint8_t>{0, 0, 0, 0, 0, 1, 0, 1}));
    EXPECT_TRUE(contains(rs.warnings.at(0).text, "stay fixed")) << rs.warnings[0].text;
    // The same text as shared_nodes_warning gives for a count over a decomposed mesh's parts.
    EXPECT_EQ(rs.warnings[0].text, shared_nodes_warning(rs.warnings[0].count, SharedNodeRule::static_wins).text);
    const auto fs = resolve_frame(mesh, fixed_edges, rs, 0);
    EXPECT_EQ(motion_of(rs.boundary, fs.motion, 4), NodeMotion{});
    EXPECT_EQ(motion_of(rs.boundary, fs.motion, 6), NodeMotion{});
    EXPECT_NEAR(motion_of(rs.boundary, fs.motion, 5).rotation[2], 10 * deg, 1e-15);
}

TEST(MotionResolve, StaticWinsOverrulesDisagreementOnNodesOfStaticMarkers) {
    Mesh mesh = chain();
    mesh.markers.push_back(test::line_marker("pins", {{1, 2}}));  // static, on both shared nodes
    const MotionSpec spec = spec_of(R"({"markers": {"a": {"translate": [1, 0]}, "b": {"translate": [0, 1]}},
                                        "shared_nodes": "static_wins"})");
    const ResolvedBoundary rb = resolve_boundary(mesh, spec);
    EXPECT_EQ(rb.boundary.moving, (std::vector<std::uint8_t>{1, 0, 0, 0, 0, 0}));
    EXPECT_THROW(resolve_boundary(mesh, spec_of(R"({"markers": {"a": {"translate": [1, 0]}, "b": {"translate": [0, 1]}}})")),
                 MeshError);
}

TEST(MotionResolve, PlanarMotionIn2D) {
    const Mesh mesh = two_squares();
    const MeshError e = mesh_error_of([&] {
        resolve_boundary(mesh, spec_of(R"({"markers": {"airfoil": {"rotate": {"angle_deg": 5, "axis": [1, 0, 0], "center": [0, 0]}}}})"));
    });
    EXPECT_EQ(e.marker(), "airfoil");
    EXPECT_TRUE(contains(e.what(), "rotates about z only")) << e.what();
    EXPECT_THROW(resolve_boundary(mesh, spec_of(R"({"markers": {"airfoil": {"translate": [0, 0, 1]}}})")), MeshError);
}

TEST(MotionResolve, MotionsNoMethodCanComputeWithAreErrorsNamingMarkerAndNode) {
    // Issue #27: check passed what deform refused (a translation of 1.7e308
    // moves a node to inf; 1e308 to a coordinate whose squares overflow).
    const Mesh mesh = two_squares();
    for (const char* json : {R"({"markers": {"airfoil": {"translate": [1.7e308, 0]}}})",
                             R"({"markers": {"airfoil": {"translate": [1e308, 1e308]}}})",
                             R"({"markers": {"airfoil": {"rotate": {"angle_deg": 1e300, "center": [0, 0]}}}})",
                             R"({"markers": {"airfoil": {"rotate": {"angle_deg": 5, "center": [1e200, 0]}}}})"}) {
        const MeshError e = mesh_error_of([&] { resolve_boundary(mesh, spec_of(json)); });
        EXPECT_EQ(e.marker(), "airfoil") << json;
        EXPECT_GE(e.index(), 4) << json;  // an airfoil node
        EXPECT_TRUE(contains(e.what(), "cannot move node " + std::to_string(e.index()))) << e.what();
        EXPECT_TRUE(contains(e.what(), "1e+150")) << e.what();
    }
    // The largest usable values pass.
    EXPECT_NO_THROW(resolve_boundary(mesh, spec_of(R"({"markers": {"airfoil": {"translate": [1e149, 0]}}})")));
}

TEST(MotionResolve, MotionLargerThanTheMeshIsAWarning) {
    const Mesh mesh = two_squares();  // diagonal 4√2 = 5.66
    const MotionSpec spec = spec_of(R"({"markers": {"airfoil": {"translate": [6, 0]}}})");
    const ResolvedBoundary rb = resolve_boundary(mesh, spec);
    ASSERT_EQ(rb.warnings.size(), 1u);
    EXPECT_TRUE(contains(rb.warnings[0].text, "marker 'airfoil' moves node")) << rb.warnings[0].text;
    EXPECT_EQ(rb.warnings[0].code, WarningCode::large_displacement);
    EXPECT_EQ(rb.warnings[0].marker, "airfoil");
    EXPECT_GE(rb.warnings[0].node, 0);
    EXPECT_NEAR(rb.warnings[0].value, 6, 1e-12);  // every airfoil node moves by 6
    const auto f = resolve_frame(mesh, spec, rb, 0);
    EXPECT_EQ(f.warnings.size(), 1u);
    const MotionSpec small = spec_of(R"({"markers": {"airfoil": {"translate": [5, 0]}}})");
    EXPECT_TRUE(resolve_boundary(mesh, small).warnings.empty());
}

TEST(MotionResolve, LargeMotionWarningsOfAMotionGivenNodeByNode) {
    // Issue #27, item 15: the same warnings for per-node motions (Python's arrays) as for a spec.
    const Mesh mesh = two_squares();
    const MotionSpec spec = spec_of(R"({"markers": {"airfoil": {"translate": [6, 0]}}})");
    const ResolvedBoundary rb = resolve_boundary(mesh, spec);
    const auto f = resolve_frame(mesh, spec, rb, 0);
    ASSERT_EQ(f.warnings.size(), 1u);
    const auto w = large_motion_warnings(mesh, rb, f.motion, "arrays");
    ASSERT_EQ(w.size(), 1u);
    EXPECT_EQ(w[0].text.substr(w[0].text.find(':')), f.warnings[0].text.substr(f.warnings[0].text.find(':')))
        << w[0].text;
    EXPECT_TRUE(w[0].text.starts_with("arrays: marker 'airfoil' moves node")) << w[0].text;
    BoundaryMotion turn(rb.boundary.nodes.size());
    for (std::size_t b = 0; b < turn.size(); ++b)
        if (rb.boundary.moving[b]) turn[b].rotation = {0, 0, 190 * deg};
    const auto t = large_motion_warnings(mesh, rb, turn, "arrays");
    ASSERT_EQ(t.size(), 1u);
    EXPECT_TRUE(contains(t[0].text, "marker 'airfoil' turns by 190 degrees in one step")) << t[0].text;
    EXPECT_EQ(t[0].code, WarningCode::large_rotation);
    EXPECT_NEAR(t[0].value, 190, 1e-9);
    EXPECT_TRUE(large_motion_warnings(mesh, rb, BoundaryMotion(rb.boundary.nodes.size()), "arrays").empty());
}

TEST(MotionResolve, SpecBuiltInCodeWithNodeTables) {
    // Tables without a source: markers with distinct tables are checked separately.
    const Mesh mesh = chain();
    MotionSpec spec;
    spec.frames.resize(1);
    NodeTable<Vec3> da;
    da.nodes = {2, 0, 1};
    da.values = {{0, 3, 0}, {0, 1, 0}, {0, 2, 0}};
    da.components = 2;
    spec.frames[0].markers["a"] = PrescribedDisplacements{da};
    const ResolvedBoundary rb = resolve_boundary(mesh, spec);
    const auto f = resolve_frame(mesh, spec, rb, 0);
    for (NodeId n = 0; n < 3; ++n) EXPECT_EQ(motion_of(rb.boundary, f.motion, n).translation[1], n + 1.0);
    EXPECT_EQ(motion_of(rb.boundary, f.motion, 3), NodeMotion{});
}

TEST(MotionResolve, AMotionForAnEmptyMarkerIsAWarningAndMovesNothing) {
    Mesh mesh = two_squares();
    mesh.markers.push_back(Marker{"slat", {}});  // SU2 MARKER_ELEMS= 0, a Gmsh physical group without elements
    const ResolvedBoundary rb = resolve_boundary(mesh, spec_of(R"({"markers": {"slat": {"translate": [0.1, 0]}}})"));
    EXPECT_EQ(rb.boundary.nodes.size(), 8u);
    EXPECT_EQ(rb.boundary.moving, std::vector<std::uint8_t>(8, 0));
    EXPECT_EQ(rb.moving_markers, std::vector<std::string>{"slat"});
    ASSERT_EQ(rb.warnings.size(), 1u);
    EXPECT_TRUE(contains(rb.warnings[0].text, "names marker 'slat', which has no elements")) << rb.warnings[0].text;
    EXPECT_EQ(rb.warnings[0].code, WarningCode::empty_named_marker);
    EXPECT_EQ(rb.warnings[0].marker, "slat");
    // An empty marker the motion does not name: no warning.
    EXPECT_TRUE(resolve_boundary(mesh, spec_of(R"({"markers": {"airfoil": {"translate": [0.1, 0]}}})")).warnings.empty());
    // A node file for it: its nodes are not on the marker, an error naming the marker and node.
    const auto dir = test::scratch_dir();
    write(dir / "d.csv", "node,dx,dy\n4,0.1,0\n");
    const MeshError e = mesh_error_of(
        [&] { resolve_boundary(mesh, spec_in(dir, R"({"markers": {"slat": {"displacement_file": "d.csv"}}})")); });
    EXPECT_EQ(e.marker(), "slat");
    EXPECT_EQ(e.index(), 4);
}

TEST(MotionResolve, AnEmptyOrAllFixedMotionWarnsThatNothingMoves) {
    const Mesh mesh = two_squares();
    for (const char* json : {R"({"markers": {}})", R"({"markers": {"airfoil": "fixed", "farfield": "fixed"}})",
                             R"({"frames": [{"markers": {}}, {"markers": {"airfoil": "fixed"}}]})"}) {
        const ResolvedBoundary rb = resolve_boundary(mesh, spec_of(json));
        ASSERT_EQ(rb.warnings.size(), 1u) << json;
        EXPECT_TRUE(contains(rb.warnings[0].text, "m.json: nothing moves")) << rb.warnings[0].text;
        EXPECT_EQ(rb.warnings[0].code, WarningCode::nothing_moves);
    }
    // A marker given a motion, even zero, moves: no warning.
    EXPECT_TRUE(resolve_boundary(mesh, spec_of(R"({"markers": {"airfoil": {"translate": [0, 0]}}})")).warnings.empty());
}

TEST(MotionResolve, BoundaryNodesAtTheSameCoordinatesAreAWarning) {
    // A zero-length boundary edge: node 9 is at node 6's coordinates, and the line 6-9 is on the airfoil.
    Mesh mesh = two_squares();
    mesh.points.insert(mesh.points.end(), {0.5, 0.5});
    const NodeId edge[] = {6, 9};
    mesh.markers[0].elements.push_back(CellType::line, edge);
    const ResolvedBoundary rb = resolve_boundary(mesh, spec_of(R"({"markers": {"airfoil": {"translate": [0.1, 0]}}})"));
    EXPECT_EQ(rb.boundary.nodes.size(), 9u);
    ASSERT_EQ(rb.warnings.size(), 1u);
    EXPECT_TRUE(contains(rb.warnings[0].text, "2 boundary nodes are at the same coordinates")) << rb.warnings[0].text;
    EXPECT_TRUE(contains(rb.warnings[0].text, "nodes 6 and 9 at (0.5, 0.5)")) << rb.warnings[0].text;
    EXPECT_EQ(rb.warnings[0].code, WarningCode::coincident_boundary_nodes);
    EXPECT_EQ(rb.warnings[0].count, 2);
    EXPECT_EQ(rb.warnings[0].node, 6);
    // Both move with the marker.
    const auto f = resolve_frame(mesh, spec_of(R"({"markers": {"airfoil": {"translate": [0.1, 0]}}})"), rb, 0);
    EXPECT_EQ(motion_of(rb.boundary, f.motion, 6), motion_of(rb.boundary, f.motion, 9));
    // A boundary element whose two nodes are one node id: no coincident pair, no warning.
    Mesh same_id = two_squares();
    const NodeId loop[] = {6, 6};
    same_id.markers[0].elements.push_back(CellType::line, loop);
    EXPECT_TRUE(
        resolve_boundary(same_id, spec_of(R"({"markers": {"airfoil": {"translate": [0.1, 0]}}})")).warnings.empty());
}

TEST(MotionResolve, ATurnOver180DegreesInOneStepIsAWarning) {
    const Mesh mesh = two_squares();
    const auto turn = [&](double degrees) {
        return resolve_boundary(mesh, spec_of(R"({"markers": {"airfoil": {"rotate": {"angle_deg": )" +
                                              std::to_string(degrees) + R"(, "center": [0, 0]}}}})"))
            .warnings;
    };
    const auto w = turn(270);
    ASSERT_EQ(w.size(), 1u);
    EXPECT_TRUE(contains(w[0].text, "marker 'airfoil' turns by 270 degrees")) << w[0].text;
    EXPECT_TRUE(turn(180).empty());
    EXPECT_TRUE(turn(-90).empty());
}

TEST(MotionResolve, AMeshWhoseMarkersAreAllEmptyIsAnError) {
    Mesh mesh = two_squares();
    for (Marker& m : mesh.markers) m.elements = {};
    const MeshError e =
        mesh_error_of([&] { resolve_boundary(mesh, spec_of(R"({"markers": {"airfoil": {"translate": [0.1, 0]}}})")); });
    EXPECT_TRUE(contains(e.what(), "no boundary nodes")) << e.what();
    EXPECT_TRUE(contains(e.what(), "every marker (airfoil, farfield) is empty")) << e.what();
    mesh.markers.clear();
    EXPECT_TRUE(contains(mesh_error_of([&] { resolve_boundary(mesh, spec_of(R"({"markers": {}})")); }).what(),
                         "it has no markers"));
}

TEST(MotionResolve, NodeDisplacementsAreTheMovedBoundaryMinusTheMeshAndZeroInside) {
    const Mesh mesh = two_squares();
    const MotionSpec spec = spec_of(R"({"markers": {"airfoil": {"rotate": {"angle_deg": 45, "center": [0.25, 0, 0]},
                                                                "translate": [0, 1]}}})");
    const ResolvedBoundary rb = resolve_boundary(mesh, spec);
    const ResolvedFrame f = resolve_frame(mesh, spec, rb, 0);
    const std::vector<double> d = node_displacements(mesh, rb.boundary, f.motion);
    ASSERT_EQ(d.size(), mesh.points.size());  // every node, dim 2
    // Node 4 at (-0.5, -0.5) goes to (0.0732233, -0.8838835 + 1) (the test above, plus the translation).
    EXPECT_NEAR(d[8], 0.0732233 + 0.5, 1e-7);
    EXPECT_NEAR(d[9], -0.8838835 + 1 + 0.5, 1e-7);
    for (int i = 0; i < 8; ++i) EXPECT_EQ(d[i], 0.0) << "farfield node " << i / 2;
    EXPECT_EQ(d[16], 0.0);  // the volume node 8 is no boundary node
    EXPECT_EQ(d[17], 0.0);
    // Every boundary node: moved_boundary_points minus the original, exactly.
    const auto p = moved_boundary_points(mesh, rb.boundary, f.motion);
    for (std::size_t b = 0; b < rb.boundary.nodes.size(); ++b)
        for (std::size_t k = 0; k < 2; ++k) {
            const auto n = static_cast<std::size_t>(rb.boundary.nodes[b]);
            EXPECT_EQ(d[2 * n + k], p[2 * b + k] - mesh.points[2 * n + k]) << "node " << n;
        }
}

TEST(ResolveFrame, CountsTheBoundaryFacesTheMotionItselfTurnsOver) {
    // SU2's hex brick with its top face turned inside a rim held by
    // static_wins: 32 of z_p's 741 faces turn over (issue #27), which the
    // frame reports as a count (DG-harmonic's guard skips such frames) and a
    // warning; under moving_wins the rim turns too and nothing folds.
    DGWARP_REQUIRE_SHARED_MESHES();
    const Mesh mesh = read_mesh(test::su2_meshes_dir() / "deformation_brick_hex_mesh_brick_hex_ffd.su2");
    std::ifstream in(test::source_dir() / "examples" / "motions" / "brick_rotate_top.json");
    std::string json((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    const MotionSpec moving_wins = spec_of(json);
    json.replace(json.find("\"moving_wins\""), 13, "\"static_wins\"");
    const MotionSpec static_wins = spec_of(json);
    const ResolvedFrame folded = resolve_frame(mesh, static_wins, resolve_boundary(mesh, static_wins), 0);
    EXPECT_EQ(folded.folded_faces, 32);
    EXPECT_TRUE(std::any_of(folded.warnings.begin(), folded.warnings.end(), [](const Warning& w) {
        return w.text.find("folds 32 of marker 'z_p''s 741 faces") != std::string::npos &&
               w.code == WarningCode::boundary_folds_faces && w.marker == "z_p" && w.count == 32 && w.element >= 0;
    }));
    EXPECT_EQ(resolve_frame(mesh, moving_wins, resolve_boundary(mesh, moving_wins), 0).folded_faces, 0);
}
