// openfoam_patch_points and openfoam_point_displacement_text: OpenFOAM's
// point order of a patch, and the pointDisplacement field written in it.
#include <gtest/gtest.h>

#include <sstream>

#include "dgwarp/core/error.hpp"
#include "dgwarp/io/openfoam/openfoam.hpp"
#include "io/openfoam/openfoam_test_support.hpp"

using namespace dgwarp;
using namespace dgwarp::test;

namespace {

/// The text of patch `name`'s dictionary in a boundaryField.
std::string point_field_patch(const std::string& text, const std::string& name) {
    const std::size_t start = text.find("\n    " + name + "\n    {\n");
    EXPECT_NE(start, std::string::npos) << name;
    if (start == std::string::npos) return {};
    return text.substr(start, text.find("\n    }\n", start) - start);
}

/// The vectors of a "nonuniform List<vector>\nN\n(\n(a b c)\n...)" value.
std::vector<std::array<double, 3>> point_field_list(const std::string& patch) {
    std::istringstream in(patch.substr(patch.find("List<vector>") + 12));
    std::size_t n = 0;
    char c = 0;
    in >> n >> c;
    EXPECT_EQ(c, '(');
    std::vector<std::array<double, 3>> values(n);
    for (auto& v : values) in >> c >> v[0] >> v[1] >> v[2] >> c;
    in >> c;
    EXPECT_EQ(c, ')');
    return values;
}

}  // namespace

TEST(OpenFoamPointField, PatchPointsInTheOrderTheFacesFirstNameThem) {
    Marker m{"wall", {}};
    const NodeId quad[] = {7, 3, 5, 9}, tri[] = {5, 3, 2}, tri2[] = {9, 2, 11};
    m.elements.push_back(CellType::quadrilateral, quad);
    m.elements.push_back(CellType::triangle, tri);
    m.elements.push_back(CellType::triangle, tri2);
    EXPECT_EQ(openfoam_patch_points(m), (std::vector<NodeId>{7, 3, 5, 9, 2, 11}));
    EXPECT_TRUE(openfoam_patch_points(Marker{"none", {}}).empty());
}

TEST(OpenFoamPointField, EachPatchListsItsPointsValuesInTheFacesFileOrder) {
    OpenFoamSource source;
    const Mesh mesh = read_openfoam(openfoam_case("mixed"), {}, &source);
    std::vector<double> d(mesh.points.size());
    for (std::size_t n = 0; n < mesh.num_points(); ++n) {  // the node's id in z: the order is visible
        d[3 * n] = 0.25 * mesh.points[3 * n] + 1.0 / 3;
        d[3 * n + 1] = -mesh.points[3 * n + 1];
        d[3 * n + 2] = static_cast<double>(n);
    }
    const std::string text = openfoam_point_displacement_text(mesh, d, source.patches, "0");
    EXPECT_NE(text.find("class       pointVectorField;"), std::string::npos);
    EXPECT_NE(text.find("location    \"0\";"), std::string::npos);
    EXPECT_NE(text.find("object      pointDisplacement;"), std::string::npos);
    EXPECT_NE(text.find("dimensions      [0 1 0 0 0 0 0];"), std::string::npos);
    EXPECT_NE(text.find("internalField   uniform (0 0 0);"), std::string::npos);

    // The order from the faces file itself: boundary faces follow the internal ones, patch after patch.
    const PolyMeshFiles files = openfoam_files("mixed");
    const auto faces = foam_ascii_faces(files.faces);
    std::size_t face = foam_ascii_labels(files.neighbour).size();
    for (const Marker& marker : mesh.markers) {
        std::vector<NodeId> expected;
        for (std::size_t f = 0; f < marker.elements.size(); ++f, ++face)
            for (NodeId n : faces[face])
                if (std::find(expected.begin(), expected.end(), n) == expected.end()) expected.push_back(n);
        const std::string patch = point_field_patch(text, marker.name);
        EXPECT_NE(patch.find("type            fixedValue;"), std::string::npos) << marker.name;
        const auto values = point_field_list(patch);
        ASSERT_EQ(values.size(), expected.size()) << marker.name;
        for (std::size_t k = 0; k < values.size(); ++k) {
            const auto n = static_cast<std::size_t>(expected[k]);
            EXPECT_EQ(values[k][0], d[3 * n]) << marker.name << " point " << k;  // exact: shortest round-trip form
            EXPECT_EQ(values[k][1], d[3 * n + 1]) << marker.name << " point " << k;
            EXPECT_EQ(values[k][2], d[3 * n + 2]) << marker.name << " point " << k;
        }
    }
    EXPECT_EQ(face, faces.size());
}

TEST(OpenFoamPointField, EqualValuesAreUniformAndConstraintPatchesKeepTheirType) {
    OpenFoamSource source;
    const Mesh mesh = read_openfoam(openfoam_case("cavity"), {}, &source);
    std::vector<double> d(mesh.points.size(), 0.0);
    for (NodeId n : marker_nodes(find_marker(mesh, "movingWall"))) d[3 * n] = 0.5;
    const std::string text = openfoam_point_displacement_text(mesh, d, source.patches, "0");
    EXPECT_NE(point_field_patch(text, "movingWall").find("value           uniform (0.5 0 0);"), std::string::npos);
    // fixedWalls shares the lid's two end points: its values differ, so a list.
    EXPECT_NE(point_field_patch(text, "fixedWalls").find("nonuniform List<vector>"), std::string::npos);
    const std::string empty = point_field_patch(text, "frontAndBack");
    EXPECT_NE(empty.find("type            empty;"), std::string::npos);
    EXPECT_EQ(empty.find("value"), std::string::npos);
    // Without patch dictionaries every patch is a fixedValue.
    EXPECT_NE(point_field_patch(openfoam_point_displacement_text(mesh, d, {}, "0"), "frontAndBack")
                  .find("fixedValue"),
              std::string::npos);
}

TEST(OpenFoamPointField, RefusesA2DMeshAndValuesOfAnotherSize) {
    OpenFoamSource source;
    const Mesh mesh = read_openfoam(openfoam_case("mixed"), {}, &source);
    const std::vector<double> short_values(mesh.points.size() - 3, 0.0);
    EXPECT_THROW(openfoam_point_displacement_text(mesh, short_values, source.patches, "0"), MeshError);
    const std::vector<double> d(mesh.points.size(), 0.0);
    EXPECT_THROW(openfoam_point_displacement_text(mesh, d, {OpenFoamPatch{}}, "0"), MeshError);
    Mesh flat;
    flat.dim = 2;
    EXPECT_THROW(openfoam_point_displacement_text(flat, {}, {}, "0"), MeshError);
}
