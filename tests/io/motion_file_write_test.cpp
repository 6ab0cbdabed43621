// write_motion_file: a spec written and read back gives the same per-node
// motions bit for bit (#17 item 12: `dgwarp case NAME --motions DIR`).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "dgwarp/cases/paper_cases.hpp"
#include "dgwarp/core/error.hpp"
#include "dgwarp/io/motion_file.hpp"
#include "dgwarp/motion/resolve_motion.hpp"
#include "support/test_paths.hpp"

using namespace dgwarp;

namespace {

/// Every frame of `spec` and of its written-and-read copy resolve to the same motions.
void expect_round_trip(const Mesh& mesh, const MotionSpec& spec, const std::filesystem::path& file) {
    write_motion_file(file, spec, mesh);
    const MotionSpec back = read_motion_file(file);
    ASSERT_EQ(frame_count(back), frame_count(spec));
    const ResolvedBoundary a = resolve_boundary(mesh, spec), b = resolve_boundary(mesh, back);
    ASSERT_EQ(a.boundary.nodes, b.boundary.nodes);
    ASSERT_EQ(a.boundary.moving, b.boundary.moving);
    for (std::size_t k = 0; k < frame_count(spec); ++k)
        EXPECT_EQ(resolve_frame(mesh, back, b.boundary, k).motion, resolve_frame(mesh, spec, a.boundary, k).motion)
            << file << " frame " << k;
}

/// A 2D square of two triangles with markers "wall" (bottom edge) and "far" (the rest).
Mesh writer_square() {
    Mesh m;
    m.dim = 2;
    m.points = {0, 0, 1, 0, 1, 1, 0, 1};
    const NodeId t0[] = {0, 1, 2}, t1[] = {0, 2, 3};
    m.cells.push_back(CellType::triangle, t0);
    m.cells.push_back(CellType::triangle, t1);
    Marker wall{"wall", {}}, far{"far field/outer", {}};
    const NodeId e0[] = {0, 1}, e1[] = {1, 2}, e2[] = {2, 3}, e3[] = {3, 0};
    wall.elements.push_back(CellType::line, e0);
    far.elements.push_back(CellType::line, e1);
    far.elements.push_back(CellType::line, e2);
    far.elements.push_back(CellType::line, e3);
    m.markers = {wall, far};
    return m;
}

}  // namespace

TEST(MotionFileWrite, EveryMotionOfTheCasesReadsBackBitForBit) {
    const auto dir = test::scratch_dir();
    // The cases whose meshes take seconds (the spheres and the wing-body take minutes).
    for (const std::string name : {"rect-box", "naca0012", "twisted-bar", "two-element", "store"}) {
        const Mesh mesh = make_case(name);
        for (const CaseMotion& m : case_motions(name, mesh)) {
            SCOPED_TRACE(name + " " + m.name);
            expect_round_trip(mesh, m.spec, dir / (name + "-" + m.name + ".json"));
        }
    }
}

TEST(MotionFileWrite, AnyRigidMotionTablesAndFramesReadBackBitForBit) {
    const auto dir = test::scratch_dir();
    const Mesh mesh = writer_square();
    // A rotation by an angle that is not a round number of degrees.
    MotionSpec turn;
    turn.frames.resize(1);
    turn.frames[0].markers["wall"] = RigidMotion{NodeMotion{{0.1, -0.2, 0}, {0, 0, -0.3}, {0.5, 0.25, 0}}};
    expect_round_trip(mesh, turn, dir / "turn.json");
    // Displacements and full motions per node, in a list of frames, under static_wins.
    MotionSpec series;
    series.shared_nodes = SharedNodeRule::static_wins;
    series.shared_tolerance = 1e-7;
    series.frames.resize(2);
    NodeTable<Vec3> d;
    d.nodes = {0, 1};
    d.values = {{1.0 / 3, 0.1, 0}, {-0.2, std::nextafter(0.4, 1.0), 0}};
    series.frames[0].markers["wall"] = PrescribedDisplacements{d};
    NodeTable<NodeMotion> n;
    n.nodes = {0, 1};
    n.values = {NodeMotion{{0.1, 0, 0}, {0, 0, 0.7}, {0.3, 0.1, 0}}, NodeMotion{{0, 0.2, 0}, {0, 0, -0.1}, {1, 0, 0}}};
    series.frames[1].markers["wall"] = PrescribedNodeMotions{n};
    series.frames[1].markers["far field/outer"] = FixedMotion{};
    expect_round_trip(mesh, series, dir / "series.json");
    EXPECT_TRUE(std::filesystem::exists(dir / "series_0_wall.csv"));
    EXPECT_TRUE(std::filesystem::exists(dir / "series_1_wall.csv"));
}

TEST(MotionFileWrite, ARotationAboutAnotherAxisIsWrittenPerNodeAndStillExact) {
    const auto dir = test::scratch_dir();
    const Mesh mesh = make_case("store");
    MotionSpec spec;
    spec.frames.resize(1);
    spec.frames[0].markers["store"] = RigidMotion{NodeMotion{{0, 0, -0.1}, {0.1, 0.2, -0.05}, {0.01, 0, 0}}};
    expect_round_trip(mesh, spec, dir / "tilt.json");
    EXPECT_TRUE(std::filesystem::exists(dir / "tilt_store.csv"));
}

TEST(MotionFileWrite, WhatItCannotWriteIsAnError) {
    const auto dir = test::scratch_dir();
    const Mesh mesh = writer_square();
    MotionSpec periodic;
    periodic.frames.resize(1);
    periodic.frames[0].markers["wall"] = PeriodicMotion{Pitch{0.1, 0, 1, 0, {0, 0, 1}, {}}, std::nullopt};
    periodic.time = TimeSteps{0.1, 10};
    EXPECT_THROW(write_motion_file(dir / "p.json", periodic, mesh), Error);
    EXPECT_FALSE(std::filesystem::exists(dir / "p.json"));
}
