// A 3D motion of a 2D case as a motion of its 2D mesh (motion/planar_motion.hpp):
// rigid motions about the normal, tables of twins, and what leaves the planes.
#include "dgwarp/motion/planar_motion.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "dgwarp/core/error.hpp"
#include "dgwarp/io/mesh_io.hpp"
#include "support/test_paths.hpp"

namespace dgwarp {
namespace {

struct Cavity {
    Mesh mesh = read_mesh(test::source_dir() / "tests/data/openfoam/cavity");
    PlanarCase planar = [this] {
        const std::size_t planes[] = {2};  // frontAndBack
        return *find_planar_case(mesh, planes).planar;
    }();
};

MotionSpec one_frame(const std::string& marker, MarkerMotion motion) {
    MotionSpec spec;
    spec.frames.emplace_back();
    spec.frames[0].markers.emplace(marker, std::move(motion));
    spec.frames[0].markers.emplace("frontAndBack", SlideMotion{});
    return spec;
}

template <class F>
std::string error_of(F f) {
    try {
        f();
    } catch (const MeshError& e) {
        return e.what();
    }
    return "";
}

TEST(PlanarMotion, RotationsAboutTheNormalBecome2DRotations) {
    const Cavity c;
    const MotionSpec spec =
        one_frame("movingWall", RigidMotion{NodeMotion{{0.01, -0.02, 0}, {0, 0, -0.3}, {0.05, 0.05, 0.005}}});
    const MotionSpec flat = planar_motion(c.planar, c.mesh, spec);
    ASSERT_EQ(flat.frames[0].markers.size(), 1u);  // the planes are left out
    const auto& rigid = std::get<RigidMotion>(flat.frames[0].markers.at("movingWall")).motion;
    EXPECT_EQ(rigid.translation, (Vec3{0.01, -0.02, 0}));
    EXPECT_EQ(rigid.rotation, (Vec3{0, 0, -0.3}));
    EXPECT_EQ(rigid.center, (Vec3{0.05, 0.05, 0}));
}

TEST(PlanarMotion, WhatLeavesThePlanesIsAnErrorNamingTheMarker) {
    const Cavity c;
    EXPECT_NE(error_of([&] {
                  planar_motion(c.planar, c.mesh,
                                one_frame("movingWall", RigidMotion{NodeMotion{{0, 0, 0.001}, {}, {}}}));
              }).find("marker 'movingWall': its translation has a component 0.001 along the normal"),
              std::string::npos);
    EXPECT_NE(error_of([&] {
                  planar_motion(c.planar, c.mesh,
                                one_frame("movingWall", RigidMotion{NodeMotion{{}, {0.1, 0, 0}, {}}}));
              }).find("turns about an axis that is not the planes' normal"),
              std::string::npos);
    MotionSpec fixed_planes = one_frame("movingWall", RigidMotion{});
    fixed_planes.frames[0].markers["frontAndBack"] = FixedMotion{};
    EXPECT_NE(error_of([&] { planar_motion(c.planar, c.mesh, fixed_planes); }).find("is a plane of the 2D case"),
              std::string::npos);
}

TEST(PlanarMotion, TablesGiveEach2DNodeOnceAndTwinsMustAgree) {
    const Cavity c;
    // Every node of movingWall (both planes) moves by (x, 0, 0) × 0.1.
    NodeTable<Vec3> table;
    table.source = "lid.csv";
    std::vector<NodeId> lid = marker_nodes(c.mesh.markers[0]);
    for (std::size_t e = 0; e < lid.size(); ++e) {
        table.nodes.push_back(lid[e]);
        table.values.push_back({0.1 * c.mesh.points[3 * static_cast<std::size_t>(lid[e])], 0, 0});
        table.lines.push_back(e + 1);
    }
    const MotionSpec flat =
        planar_motion(c.planar, c.mesh, one_frame("movingWall", PrescribedDisplacements{table}));
    const auto& t = std::get<PrescribedDisplacements>(flat.frames[0].markers.at("movingWall")).displacements;
    ASSERT_EQ(t.nodes.size(), lid.size() / 2);  // each twin pair once
    EXPECT_EQ(t.components, 2);
    for (std::size_t e = 0; e < t.nodes.size(); ++e) {
        const auto j = static_cast<std::size_t>(t.nodes[e]);
        EXPECT_EQ(t.values[e], (Vec3{0.1 * c.planar.mesh.points[2 * j], 0, 0}));
    }
    table.values.back()[1] = 0.5;  // a back node moving unlike its front twin
    EXPECT_NE(error_of([&] { planar_motion(c.planar, c.mesh, one_frame("movingWall", PrescribedDisplacements{table})); })
                  .find("are twins across the 2D case's layer but move differently"),
              std::string::npos);
}

}  // namespace
}  // namespace dgwarp
