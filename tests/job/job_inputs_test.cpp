// A deformation job's inputs from files (job/job_inputs.hpp): OpenFOAM's 2D
// case deformed as its 2D mesh and written back in 3D, names the output
// cannot hold, an SU2 configuration's symmetry markers, and the cells already
// inverted in the input.
#include "dgwarp/job/job_inputs.hpp"

#include <gtest/gtest.h>

#include <fstream>

#include "dgwarp/core/error.hpp"
#include "dgwarp/io/motion_file.hpp"
#include "io/openfoam/openfoam_test_support.hpp"

using namespace dgwarp;
using namespace dgwarp::test;

namespace {

JobInputs read_inputs(const std::filesystem::path& mesh, const MotionSpec& spec) {
    JobInputs in;
    in.spec = spec;
    in.mesh = read_mesh(mesh, {}, {}, in.extras);
    return in;
}

MotionSpec translate(const std::string& marker, double dx) {
    return parse_motion_file(R"({"markers": {")" + marker + R"(": {"translate": [)" + std::to_string(dx) + ", 0, 0]}}}",
                             "m.json", std::filesystem::temp_directory_path());  // names no file
}

}  // namespace

TEST(JobInputs, AnOpenFoam2dCaseIsDeformedAsItsPlaneAndWrittenIn3d) {
    JobInputs in = read_inputs(openfoam_case("cavity"), translate("movingWall", 0.001));
    const Mesh read = in.mesh;
    classify_inputs(in, {});
    ASSERT_TRUE(in.planar);
    EXPECT_EQ(in.mesh.dim, 2);
    EXPECT_EQ(in.file_mesh.points, read.points);
    EXPECT_EQ(&output_mesh(in), &in.file_mesh);
    // The 2D mesh's points lifted back are the file's.
    std::vector<double> buffer;
    const std::span<const double> lifted = output_points(in, in.mesh.points, buffer);
    ASSERT_EQ(lifted.size(), read.points.size());
    EXPECT_TRUE(std::equal(lifted.begin(), lifted.end(), read.points.begin()));
    EXPECT_FALSE(in.boundary.boundary.nodes.empty());
    EXPECT_EQ(in.boundary.moving_markers, std::vector<std::string>{"movingWall"});
    // The original cells, measured beside other work, and a frame written as the file's mesh.
    bool worked = false;
    measure_original_cells(in, [&] { worked = true; });
    EXPECT_TRUE(worked);
    EXPECT_EQ(in.original.summary.cells, static_cast<std::int64_t>(in.mesh.cells.size()));
    EXPECT_EQ(in.original.summary.inverted, 0);
    std::vector<double> points(lifted.begin(), lifted.end());
    points[0] += 1e-3;
    const std::vector<double> given = points;
    const auto out = scratch_dir() / "frame.vtu";
    write_output_mesh(in, out, points, {}, {});
    EXPECT_EQ(points, given);                   // swapped back
    EXPECT_EQ(in.file_mesh.points, read.points);  // and the mesh's own
    EXPECT_EQ(read_mesh(out).points, given);
}

TEST(JobInputs, NamesTheOutputCannotHoldAreRenamedInTheMotionTooWithAWarning) {
    JobInputs in = read_inputs(openfoam_case("cavity"), translate("moving wall", 0.001));
    for (Marker& m : in.mesh.markers)
        if (m.name == "movingWall") m.name = "moving wall";
    InputSettings settings;
    settings.writable_for = (scratch_dir() / "case/").string();
    settings.rename_option = "--rename-marker";
    classify_inputs(in, settings);
    ASSERT_EQ(in.renamed_for_output.size(), 1u);
    EXPECT_EQ(in.renamed_for_output[0].from, "moving wall");
    EXPECT_EQ(in.boundary.moving_markers, std::vector<std::string>{in.renamed_for_output[0].to});
    bool warned = false;
    for (const Warning& w : in.boundary.warnings)
        warned |= w.marker == in.renamed_for_output[0].to &&
                  w.text.find("cannot hold the marker name 'moving wall'") != std::string::npos &&
                  w.text.find("(--rename-marker 'moving wall=NEW' names it otherwise)") != std::string::npos;
    EXPECT_TRUE(warned);
}

TEST(JobInputs, AnSu2ConfigurationsSymmetryMarkerMustBeInTheMesh) {
    const auto config = scratch_dir() / "case.cfg";
    std::ofstream(config) << "% a comment\nMARKER_SYM= ( nowhere )\n";
    JobInputs in = read_inputs(openfoam_case("cavity"), translate("movingWall", 0.001));
    InputSettings settings;
    settings.su2_config = config.string();
    try {
        classify_inputs(in, settings);
        FAIL() << "a MARKER_SYM marker the mesh has not was taken";
    } catch (const MeshError& e) {
        EXPECT_NE(std::string(e.what()).find(config.string() + ":2: MARKER_SYM: "), std::string::npos) << e.what();
        EXPECT_EQ(e.marker(), "nowhere");
    }
}
