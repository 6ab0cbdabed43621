// `dgwarp motion-field`: the boundary displacement of a motion as CSV and as
// OpenFOAM's pointDisplacement (what bench/peers/openfoam.sh gives moveMesh).
#include <gtest/gtest.h>

#include <sstream>

#include "dgwarp/io/mesh_io.hpp"
#include "dgwarp/io/openfoam/openfoam.hpp"
#include "io/openfoam/openfoam_test_support.hpp"
#include "support/test_paths.hpp"

using namespace dgwarp;
using namespace dgwarp::test;

namespace {

const char* motion_field_lift = R"({"markers": {"top": {"translate": [0, 0, 0.05]}}})";

}  // namespace

TEST(CliMotionField, CsvListsEveryBoundaryNodeWithItsDisplacement) {
    const auto dir = scratch_dir();
    const auto motion = write_text(dir / "lift.json", motion_field_lift);
    const auto c = openfoam_case("mixed");
    const CommandResult r = run_cli("motion-field " + quoted(c) + " -m " + quoted(motion) + " -o " +
                                    quoted(dir / "lift.csv"));
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(r.out.find("moving markers: top\n"), std::string::npos) << r.out;
    const Mesh mesh = read_mesh(c);
    std::vector<NodeId> boundary;
    for (const Marker& m : mesh.markers)
        for (NodeId n : marker_nodes(m)) boundary.push_back(n);
    std::sort(boundary.begin(), boundary.end());
    boundary.erase(std::unique(boundary.begin(), boundary.end()), boundary.end());
    const auto top = marker_nodes(find_marker(mesh, "top"));

    std::istringstream csv(slurp(dir / "lift.csv"));
    std::string line;
    std::getline(csv, line);
    EXPECT_EQ(line, "node,dx,dy,dz");
    std::size_t k = 0;
    while (std::getline(csv, line)) {
        ASSERT_LT(k, boundary.size());
        const NodeId n = boundary[k];
        const bool on_top = std::binary_search(top.begin(), top.end(), n);
        // The new position minus the old, as deform moves the node (z + 0.05 rounded, minus z).
        const double z = mesh.points[3 * static_cast<std::size_t>(n) + 2];
        std::istringstream fields(line);
        NodeId id = -1;
        double dx = -1, dy = -1, dz = -1;
        char c1 = 0, c2 = 0, c3 = 0;
        fields >> id >> c1 >> dx >> c2 >> dy >> c3 >> dz;
        EXPECT_EQ(id, n) << line;
        EXPECT_EQ(dx, 0.0) << line;
        EXPECT_EQ(dy, 0.0) << line;
        EXPECT_EQ(dz, on_top ? (z + 0.05) - z : 0.0) << line;
        ++k;
    }
    EXPECT_EQ(k, boundary.size());
}

TEST(CliMotionField, PointDisplacementGoesToTheCaseTimeFolder) {
    const auto dir = scratch_dir();
    const auto motion = write_text(dir / "lift.json", motion_field_lift);
    std::filesystem::copy(openfoam_case("mixed"), dir / "mixed", std::filesystem::copy_options::recursive);
    const auto c = dir / "mixed";
    const CommandResult r =
        run_cli("motion-field " + quoted(c) + " -m " + quoted(motion) + " -o " + quoted(c) + " --foam-time 0.5");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const std::string text = slurp(c / "0.5" / "pointDisplacement");
    OpenFoamSource source;
    const Mesh mesh = read_openfoam(c, {}, &source);
    std::vector<double> d(mesh.points.size(), 0.0);
    for (NodeId n : marker_nodes(find_marker(mesh, "top"))) d[3 * n + 2] = (mesh.points[3 * n + 2] + 0.05) - mesh.points[3 * n + 2];
    EXPECT_EQ(text, openfoam_point_displacement_text(mesh, d, source.patches, "0.5"));

    // Not an OpenFOAM input: refused, naming the way (exit 2), nothing written.
    const auto su2 = dir / "mixed.su2";
    ASSERT_EQ(run_cli("convert " + quoted(c) + " " + quoted(su2) + " -q").exit_code, 0);
    const CommandResult bad = run_cli("motion-field " + quoted(su2) + " -m " + quoted(motion) + " -o " +
                                      quoted(dir / "other/"));
    EXPECT_EQ(bad.exit_code, 2);
    EXPECT_NE(bad.err.find("dgwarp convert"), std::string::npos) << bad.err;
    EXPECT_FALSE(std::filesystem::exists(dir / "other" / "0" / "pointDisplacement"));
    // Neither .csv nor a folder; a frame the motion does not have: usage errors.
    EXPECT_EQ(run_cli("motion-field " + quoted(c) + " -m " + quoted(motion) + " -o " + quoted(dir / "d.vtu")).exit_code,
              1);
    EXPECT_EQ(run_cli("motion-field " + quoted(c) + " -m " + quoted(motion) + " -o " + quoted(dir / "d.csv") +
                      " --frame 1")
                  .exit_code,
              1);
}
