// write_motion_file: what it writes reads back to the same motions, bit for
// bit, for every case motion and every kind of motion.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <numbers>
#include <utility>

#include "dgwarp/cases/paper_cases.hpp"
#include "dgwarp/io/motion_file.hpp"
#include "dgwarp/motion/resolve_motion.hpp"
#include "motion/motion_test_meshes.hpp"
#include "support/test_paths.hpp"

using namespace dgwarp;

namespace {

template <class T>
bool mfw_same_bits(const T& a, const T& b) {
    return std::memcmp(&a, &b, sizeof(T)) == 0;
}

template <class Value>
void mfw_expect_same_table(const NodeTable<Value>& a, const NodeTable<Value>& b, const std::string& what) {
    EXPECT_EQ(a.nodes, b.nodes) << what;
    EXPECT_EQ(a.components, b.components) << what;
    ASSERT_EQ(a.values.size(), b.values.size()) << what;
    for (std::size_t e = 0; e < a.values.size(); ++e)
        EXPECT_TRUE(mfw_same_bits(a.values[e], b.values[e])) << what << ", entry " << e;
}

/// The two motions are the same, bit for bit (a table's source and lines aside).
void mfw_expect_same_motion(const MarkerMotion& a, const MarkerMotion& b, const std::string& what) {
    ASSERT_EQ(a.index(), b.index()) << what << ": " << motion_kind_name(a) << " read back as " << motion_kind_name(b);
    if (const auto* r = std::get_if<RigidMotion>(&a)) {
        EXPECT_TRUE(mfw_same_bits(r->motion, std::get<RigidMotion>(b).motion)) << what;
    }
    if (const auto* p = std::get_if<PeriodicMotion>(&a)) {
        const auto& q = std::get<PeriodicMotion>(b);
        ASSERT_EQ(p->pitch.has_value(), q.pitch.has_value()) << what;
        ASSERT_EQ(p->plunge.has_value(), q.plunge.has_value()) << what;
        if (p->pitch) {
            EXPECT_TRUE(mfw_same_bits(*p->pitch, *q.pitch)) << what;
        }
        if (p->plunge) {
            EXPECT_TRUE(mfw_same_bits(*p->plunge, *q.plunge)) << what;
        }
    }
    if (const auto* d = std::get_if<PrescribedDisplacements>(&a))
        mfw_expect_same_table(d->displacements, std::get<PrescribedDisplacements>(b).displacements, what);
    if (const auto* s = std::get_if<PrescribedPositions>(&a))
        mfw_expect_same_table(s->positions, std::get<PrescribedPositions>(b).positions, what);
    if (const auto* n = std::get_if<PrescribedNodeMotions>(&a))
        mfw_expect_same_table(n->motions, std::get<PrescribedNodeMotions>(b).motions, what);
    if (const auto* c = std::get_if<CyclicMotion>(&a)) {
        EXPECT_EQ(c->partner, std::get<CyclicMotion>(b).partner) << what;
    }
}

void mfw_expect_same_spec(const MotionSpec& a, const MotionSpec& b, const std::string& what) {
    ASSERT_EQ(a.frames.size(), b.frames.size()) << what;
    for (std::size_t f = 0; f < a.frames.size(); ++f) {
        ASSERT_EQ(a.frames[f].markers.size(), b.frames[f].markers.size()) << what << ", frame " << f;
        for (const auto& [name, motion] : a.frames[f].markers) {
            ASSERT_TRUE(b.frames[f].markers.count(name)) << what << ": marker " << name;
            mfw_expect_same_motion(motion, b.frames[f].markers.at(name), what + ", frame " + std::to_string(f) + ", " + name);
        }
    }
    mfw_expect_same_motion(a.default_motion, b.default_motion, what + ", default");
    ASSERT_EQ(a.time.has_value(), b.time.has_value()) << what;
    if (a.time) {
        EXPECT_TRUE(mfw_same_bits(*a.time, *b.time)) << what;
    }
    EXPECT_EQ(a.shared_nodes, b.shared_nodes) << what;
    EXPECT_TRUE(mfw_same_bits(a.shared_tolerance, b.shared_tolerance)) << what;
}

/// A 3D stand-in for the meshes made by Gmsh (squeezed-sphere, wing-body,
/// store): the cube's faces, with the markers their motions move.
Mesh mfw_stand_in_3d() {
    Mesh m = test::cube_faces();
    m.markers[0].name = "sphere";
    m.markers[1].name = "wing";
    m.markers[2].name = "store";
    return m;
}

}  // namespace

TEST(MotionFileWrite, EveryCaseMotionReadsBackBitForBit) {
    const auto dir = test::scratch_dir();
    for (const std::string& name : case_names()) {
        const bool by_gmsh = name == "squeezed-sphere" || name == "wing-body" || name == "store";
        const Mesh mesh = by_gmsh ? mfw_stand_in_3d() : make_case(name);
        for (const CaseMotion& cm : case_motions(name, mesh)) {
            const auto path = dir / name / (cm.name + ".json");
            std::filesystem::create_directories(path.parent_path());
            const auto written = write_motion_file(path, cm.spec, cm.description);
            ASSERT_FALSE(written.empty());
            EXPECT_EQ(written.back(), path);
            const MotionSpec read = read_motion_file(path);
            mfw_expect_same_spec(cm.spec, read, name + " " + cm.name);
            // And what the methods get: every boundary node's motion.
            const ResolvedBoundary a = resolve_boundary(mesh, cm.spec), b = resolve_boundary(mesh, read);
            EXPECT_EQ(a.boundary.nodes, b.boundary.nodes);
            EXPECT_EQ(a.boundary.moving, b.boundary.moving);
            const BoundaryMotion ma = resolve_frame(mesh, cm.spec, a, 0).motion;
            const BoundaryMotion mb = resolve_frame(mesh, read, b, 0).motion;
            ASSERT_EQ(ma.size(), mb.size());
            EXPECT_EQ(std::memcmp(ma.data(), mb.data(), ma.size() * sizeof(NodeMotion)), 0) << name << " " << cm.name;
        }
    }
}

TEST(MotionFileWrite, EveryKindOfMotionReadsBackBitForBit) {
    const auto dir = test::scratch_dir();
    // Built in code: frames with every kind a frame may hold, a table shared by two markers.
    MotionSpec frames;
    frames.frames.resize(2);
    NodeTable<Vec3> displacements{{4, 5, 6, 7}, {{0.1, 0, 1e-300}, {0, -0.2, 3}, {1.0 / 3, 0, 0}, {0, 0, -0.0}}, 3, "", {}};
    NodeTable<Vec3> positions{{0, 1, 2, 3}, {{0.5, 0.25, 0}, {1, 2, 3}, {4, 5, 6}, {7, 8, 9}}, 3, "surface.dat", {}};
    NodeTable<NodeMotion> twist{{0, 2, 4, 6}, {}, 3, "", {}};
    for (int i = 0; i < 4; ++i) twist.values.push_back({{0.1 * i, 0, 0}, {0.01 * i, 0.02, 0.7}, {0, 0.5, 1.0 / 7}});
    frames.frames[0].markers["top"] = PrescribedDisplacements{displacements};
    frames.frames[0].markers["side"] = PrescribedNodeMotions{twist};
    frames.frames[0].markers["bottom"] = FixedMotion{};
    frames.frames[0].markers["sym"] = frames.frames[1].markers["sym"] = SlideMotion{};
    frames.frames[0].markers["in"] = frames.frames[1].markers["in"] = CyclicMotion{"out"};
    // A rotation vector from degrees (17°), as the case motions make them.
    frames.frames[1].markers["top"] = RigidMotion{{{1, 2, 3}, {0, 17 * (std::numbers::pi / 180), 0}, {0.5, 0.5, 0.5}}};
    frames.frames[1].markers["bottom"] = PrescribedPositions{positions};  // one source: one file for both
    frames.frames[1].markers["side"] = PrescribedPositions{positions};
    frames.default_motion = RigidMotion{{{0, 0, 0.25}, {}, {}}};
    frames.shared_nodes = SharedNodeRule::static_wins;
    frames.shared_tolerance = 1e-6;
    // Periodic: pitch and plunge with the angles a user writes in degrees.
    const MotionSpec periodic = parse_motion_file(R"({"markers": {"top": {"periodic": {
        "pitch": {"amplitude_deg": 7.3, "mean_deg": -2.1, "frequency": 0.7, "phase_deg": 33.3, "axis": [0, 1, 0], "center": [1, 0.5]},
        "plunge": {"amplitude": [0, 0.1, 0.05], "frequency": 1.3, "phase_deg": 90}}}},
      "time": {"time_step": 0.01, "steps": 250}})",
                                                  "p.json", dir);
    // Rigid motions read from degrees, each about a coordinate axis: exact.
    const MotionSpec degrees = parse_motion_file(R"({"frames": [
        {"markers": {"top": {"rotate": {"angle_deg": 0.1, "axis": [1, 0, 0], "center": [0, 0, 1]}}}},
        {"markers": {"top": {"rotate": {"angle_deg": -179.9, "axis": [0, 0, -1], "center": [0, 0, 1]}, "translate": [1e-9, 0]}}},
        {"markers": {"top": {"rotate": {"angle_deg": 123.456, "axis": [0, 2, 0], "center": [0, 0, 1]}}}}]})",
                                                 "d.json", dir);
    for (const auto& [stem, spec] : {std::pair{"frames", frames}, {"periodic", periodic}, {"degrees", degrees}}) {
        const auto path = dir / (std::string(stem) + ".json");
        write_motion_file(path, spec);
        mfw_expect_same_spec(spec, read_motion_file(path), stem);
    }
    // The shared positions table is one file, the motion file comes last.
    const auto written = write_motion_file(dir / "frames.json", frames);
    ASSERT_EQ(written.size(), 4u);  // node motions, displacements, positions, the motion file
    EXPECT_EQ(written[2].extension(), ".dat");
    EXPECT_EQ(written.back(), dir / "frames.json");
}

TEST(MotionFileWrite, ARotationAboutAnOtherAxisReadsBackWithinRounding) {
    const auto dir = test::scratch_dir();
    MotionSpec spec;
    spec.frames.resize(1);
    const Vec3 w{0.3, -0.2, 0.1};
    spec.frames[0].markers["top"] = RigidMotion{{{0, 0, 0}, w, {1, 2, 3}}};
    write_motion_file(dir / "m.json", spec);
    const NodeMotion read = std::get<RigidMotion>(read_motion_file(dir / "m.json").frames[0].markers.at("top")).motion;
    for (int i = 0; i < 3; ++i) EXPECT_NEAR(read.rotation[i], w[i], 4e-16) << i;
    EXPECT_EQ(read.center, (Vec3{1, 2, 3}));
}
