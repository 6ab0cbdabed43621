// Markers that slide by the type their file gives them (io/marker_types.hpp),
// and the 2D cases OpenFOAM's empty and wedge patches make.
#include "dgwarp/io/marker_types.hpp"

#include <gtest/gtest.h>

#include "support/cgns_test_writer.hpp"
#include "support/test_paths.hpp"

namespace dgwarp {
namespace {

Mesh read_case(const std::string& name, MeshExtras& extras) {
    return read_mesh(test::source_dir() / "tests/data/openfoam" / name, {}, {}, extras);
}

MotionSpec lid_motion() {
    MotionSpec spec;
    spec.frames.emplace_back();
    spec.frames[0].markers["movingWall"] = RigidMotion{NodeMotion{{0.01, 0, 0}, {}, {}}};
    return spec;
}

TEST(MarkerTypes, OpenFoamEmptyPatchesSlideAndMakeThe2DCase) {
    MeshExtras extras;
    const Mesh mesh = read_case("cavity", extras);
    EXPECT_EQ(marker_types(mesh, extras), (std::vector<std::string>{"wall", "wall", "empty"}));
    MotionSpec spec = lid_motion();
    const TypedMotion typed = apply_marker_types(mesh, extras, spec);
    EXPECT_EQ(typed.sliding, (std::vector<std::string>{"frontAndBack"}));
    EXPECT_TRUE(std::holds_alternative<SlideMotion>(spec.frames[0].markers.at("frontAndBack")));
    ASSERT_TRUE(typed.planar.has_value()) << typed.not_planar;
    EXPECT_EQ(typed.planar->mesh.num_points(), 20u);
}

TEST(MarkerTypes, AMotionThatNamesThePlanesOrGivesADefaultKeepsThemAsItSays) {
    MeshExtras extras;
    const Mesh mesh = read_case("cavity", extras);
    MotionSpec named = lid_motion();
    named.frames[0].markers["frontAndBack"] = FixedMotion{};
    TypedMotion typed = apply_marker_types(mesh, extras, named);
    EXPECT_TRUE(typed.sliding.empty());
    EXPECT_FALSE(typed.planar.has_value());  // held: the case stays 3D
    EXPECT_TRUE(typed.not_planar.empty());

    MotionSpec with_default = lid_motion();
    with_default.default_given = true;  // "default": "fixed" in the file
    typed = apply_marker_types(mesh, extras, with_default);
    EXPECT_TRUE(typed.sliding.empty());
    EXPECT_FALSE(typed.planar.has_value());
    EXPECT_EQ(with_default.frames[0].markers.count("frontAndBack"), 0u);
}

TEST(MarkerTypes, MovingConesWedgesMakeAnAxisymmetricCase) {
    MeshExtras extras;
    const Mesh mesh = read_case("moving-cone", extras);
    MotionSpec spec;
    spec.frames.emplace_back();
    spec.frames[0].markers["movingWall"] = RigidMotion{NodeMotion{{0.001, 0, 0}, {}, {}}};
    const TypedMotion typed = apply_marker_types(mesh, extras, spec);
    // The axis patch has no face: it does not slide in 3D; it is the 2D mesh's axis marker.
    EXPECT_EQ(typed.sliding, (std::vector<std::string>{"back", "front"}));
    ASSERT_TRUE(typed.planar.has_value()) << typed.not_planar;
    EXPECT_TRUE(typed.planar->wedge);
    EXPECT_EQ(typed.planar->axis_marker, "axis");
    EXPECT_EQ(typed.planar->mesh.cells.size(), mesh.cells.size());
}

TEST(MarkerTypes, CgnsSymmetryPlanesSlide) {
    // One tetrahedron: its face z = 0 a symmetry plane, its face y = 0 a wall.
    test::TestZone z;
    z.x = {0, 1, 0, 0};
    z.y = {0, 0, 1, 0};
    z.z = {0, 0, 0, 1};
    z.sections = {{"Cells", test::cgns_code::TETRA_4, 1, {1, 2, 3, 4}}};
    z.bcs = {{"mirror", "", test::cgns_code::Vertex, false, {1, 2, 3}, test::cgns_code::BCSymmetryPlane},
             {"wall", "", test::cgns_code::Vertex, false, {1, 2, 4}}};
    const auto dir = test::scratch_dir();
    test::write_test_cgns(dir / "mirror.cgns", 3, {z});
    MeshExtras extras;
    const Mesh mesh = read_mesh(dir / "mirror.cgns", {}, {}, extras);
    EXPECT_EQ(markers_sliding_by_type(mesh, extras), (std::vector<std::string>{"mirror"}));
    MotionSpec spec;
    spec.frames.emplace_back();
    const TypedMotion typed = apply_marker_types(mesh, extras, spec);
    EXPECT_EQ(typed.sliding, (std::vector<std::string>{"mirror"}));
    EXPECT_FALSE(typed.planar.has_value());
}

TEST(MarkerTypes, FilesWithoutTypesSlideNothing) {
    MeshExtras extras;
    const Mesh mesh = read_mesh(test::source_dir() / "tests/data/cgns/tet.cgns", {}, {}, extras);
    MotionSpec spec;
    spec.frames.emplace_back();
    EXPECT_TRUE(apply_marker_types(mesh, extras, spec).sliding.empty());
    MeshExtras none;
    EXPECT_EQ(marker_types(mesh, none), std::vector<std::string>(mesh.markers.size()));
}

TEST(MarkerTypes, OpenFoamCyclicPatchesAndTheirNeighbourPatchAreCoupledUnlessNamed) {
    MeshExtras extras;
    const Mesh mesh = read_case("channel-cyclic", extras);
    ASSERT_TRUE(extras.openfoam);
    EXPECT_EQ(cyclic_neighbour(extras.openfoam->patches[6]), "inout1_half1");
    EXPECT_EQ(cyclic_neighbour(extras.openfoam->patches[0]), "");  // bottomWall
    MotionSpec spec;
    spec.frames.emplace_back();
    spec.frames[0].markers["bottomWall"] = RigidMotion{NodeMotion{{0.01, 0, 0}, {}, {}}};
    spec.frames[0].markers["inout1_half1"] = FixedMotion{};  // named: that pair is not coupled
    const TypedMotion typed = apply_marker_types(mesh, extras, spec);
    const std::vector<std::pair<std::string, std::string>> coupled{
        {"sides1_half0", "sides1_half1"}, {"sides2_half0", "sides2_half1"}, {"inout2_half0", "inout2_half1"}};
    EXPECT_EQ(typed.coupled, coupled);
    EXPECT_EQ(typed.uncoupled, (std::vector<std::string>{"inout1_half0", "inout1_half1"}));
    EXPECT_EQ(std::get<CyclicMotion>(spec.frames[0].markers.at("sides1_half1")).partner, "sides1_half0");
    EXPECT_EQ(spec.frames[0].markers.count("inout1_half0"), 0u);
    // A default in the motion: nothing is coupled.
    MotionSpec with_default;
    with_default.frames.emplace_back();
    with_default.default_given = true;
    const TypedMotion none = apply_marker_types(mesh, extras, with_default);
    EXPECT_TRUE(none.coupled.empty());
    EXPECT_EQ(none.uncoupled.size(), 8u);
}

}  // namespace
}  // namespace dgwarp
