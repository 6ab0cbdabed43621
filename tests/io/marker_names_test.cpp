// Marker names across formats (io/marker_names.hpp): renames, and names an
// output cannot hold made into names it can.
#include "dgwarp/io/marker_names.hpp"

#include <gtest/gtest.h>

#include "dgwarp/core/error.hpp"

namespace dgwarp {
namespace {

Mesh named(const std::vector<std::string>& names) {
    Mesh mesh;
    for (const auto& n : names) mesh.markers.push_back({n, {}});
    return mesh;
}

std::vector<std::string> names_of(const Mesh& mesh) {
    std::vector<std::string> n;
    for (const Marker& m : mesh.markers) n.push_back(m.name);
    return n;
}

TEST(MarkerNames, RenamesParseAtTheLastEqualsSign) {
    EXPECT_EQ(marker_rename_problem("a=b"), "");
    EXPECT_NE(marker_rename_problem("ab"), "");
    EXPECT_NE(marker_rename_problem("=b"), "");
    EXPECT_NE(marker_rename_problem("a="), "");
    const MarkerRename r = parse_marker_rename("x=1=wing");
    EXPECT_EQ(r.from, "x=1");
    EXPECT_EQ(r.to, "wing");
}

TEST(MarkerNames, RenamingNeedsTheMarkerAndAFreeName) {
    Mesh mesh = named({"UserDefined 1", "far"});
    rename_markers(mesh, {{"UserDefined 1", "wing"}});
    EXPECT_EQ(names_of(mesh), (std::vector<std::string>{"wing", "far"}));
    EXPECT_THROW(rename_markers(mesh, {{"nosuch", "x"}}), MeshError);
    EXPECT_THROW(rename_markers(mesh, {{"wing", "far"}}), MeshError);
    rename_markers(mesh, {{"wing", "wing"}});  // to itself: nothing changes
    EXPECT_EQ(names_of(mesh), (std::vector<std::string>{"wing", "far"}));
}

TEST(MarkerNames, OpenFoamNamesBecomeOneWordAndStayDistinct) {
    Mesh mesh = named({"UserDefined 1", "UserDefined_1", "wall(2)", " padded ", "ok"});
    const auto made = make_marker_names_writable(mesh, "case/");
    EXPECT_EQ(names_of(mesh), (std::vector<std::string>{"UserDefined_1_2", "UserDefined_1", "wall_2_", "padded", "ok"}));
    ASSERT_EQ(made.size(), 3u);
    EXPECT_EQ(made[0].from, "UserDefined 1");
    EXPECT_EQ(made[0].to, "UserDefined_1_2");
    for (const Marker& m : mesh.markers) EXPECT_TRUE(is_openfoam_word(m.name)) << m.name;
}

TEST(MarkerNames, CgnsNamesAreCutTo32CharactersWithoutSlashes) {
    Mesh mesh = named({std::string(40, 'w'), "a/b", "Tri Group 1"});
    const auto made = make_marker_names_writable(mesh, "out.cgns");
    EXPECT_EQ(names_of(mesh), (std::vector<std::string>{std::string(32, 'w'), "a_b", "Tri Group 1"}));  // blanks inside are fine
    EXPECT_EQ(made.size(), 2u);
    // Other formats hold every name.
    Mesh any = named({"a b/c(d)"});
    EXPECT_TRUE(make_marker_names_writable(any, "out.vtu").empty());
    EXPECT_TRUE(make_marker_names_writable(any, "out.msh").empty());
}

}  // namespace
}  // namespace dgwarp
