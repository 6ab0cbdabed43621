// A run's frames into an OpenFOAM case folder (io/openfoam/openfoam_frames.hpp),
// and the OpenFOAM format's input and output files (mesh_input_files,
// check_mesh_output): against the committed cases, read back.
#include <gtest/gtest.h>

#include "dgwarp/core/error.hpp"
#include "dgwarp/io/mesh_io.hpp"
#include "dgwarp/io/openfoam/openfoam_frames.hpp"
#include "dgwarp/io/su2/su2.hpp"
#include "io/openfoam/openfoam_test_support.hpp"

using namespace dgwarp;
using namespace dgwarp::test;
namespace fs = std::filesystem;

TEST(OpenFoamFrames, TimeNamesAsOpenFoamNamesThem) {
    EXPECT_EQ(openfoam_time_names(std::vector<double>{}), std::vector<std::string>{"0"});
    EXPECT_EQ(openfoam_time_names(std::vector<double>{0.25}), std::vector<std::string>{"0"});  // a single frame
    EXPECT_EQ(openfoam_time_names(std::vector<double>{0, 0.001, 1e-05, 2.5}),
              (std::vector<std::string>{"0", "0.001", "1e-05", "2.5"}));
    // Six significant digits unless two times would share a name.
    EXPECT_EQ(openfoam_time_names(std::vector<double>{1.0000001, 2}), (std::vector<std::string>{"1", "2"}));
    EXPECT_EQ(openfoam_time_names(std::vector<double>{1.0000001, 1.0000002}),
              (std::vector<std::string>{"1.0000001", "1.0000002"}));
    // Repeated times: the frame numbers.
    EXPECT_EQ(openfoam_time_names(std::vector<double>{0, 0, 1}), (std::vector<std::string>{"0", "1", "2"}));
}

TEST(OpenFoamFrames, AMotionsFramesAreNamedByTheirTimesAndTimeNamesAreNumbersOrConstant) {
    MotionSpec series;
    series.frames.resize(3);  // a frames list: no times, so the frame numbers
    EXPECT_EQ(openfoam_frame_time_names(series), (std::vector<std::string>{"0", "1", "2"}));
    MotionSpec periodic;
    periodic.frames.resize(1);
    periodic.time = TimeSteps{0.25, 3};
    EXPECT_EQ(openfoam_frame_time_names(periodic), (std::vector<std::string>{"0", "0.25", "0.5"}));
    for (const char* ok : {"0", "0.5", "1e-05", "constant", "12"}) EXPECT_TRUE(is_openfoam_time_name(ok)) << ok;
    for (const char* bad : {"", "later", "0.5s", "Constant", "1,5"}) EXPECT_FALSE(is_openfoam_time_name(bad)) << bad;
}

TEST(OpenFoamFrames, FramesOfACaseAreItsTimeFoldersReadBackWithItsFaces) {
    const fs::path input = openfoam_case("cavity");
    MeshExtras extras;
    const Mesh mesh = read_mesh(input, {}, {}, extras);
    const fs::path out = scratch_dir() / "frames";
    const std::vector<std::string> times = openfoam_time_names(std::vector<double>{0.5, 1});
    ASSERT_EQ(times, (std::vector<std::string>{"0.5", "1"}));
    check_openfoam_frame_outputs(out, times, input, mesh_input_files(input));
    write_openfoam_frame_base(out, times[0], mesh, extras);
    for (const char* name : poly_mesh_file_names)
        EXPECT_EQ(slurp(out / "constant/polyMesh" / name), slurp(input / "constant/polyMesh" / name)) << name;
    for (std::size_t k = 0; k < times.size(); ++k) {
        std::vector<double> points = mesh.points;
        for (std::size_t i = 0; i < points.size(); i += 3) points[i] += 0.001 * static_cast<double>(k + 1);
        const fs::path file = write_openfoam_frame_points(out, times[k], points, extras);
        EXPECT_EQ(file, out / times[k] / "polyMesh" / "points");
        const Mesh frame = read_mesh(out / times[k]);  // the time folder's points with constant's faces
        EXPECT_EQ(frame.points, points) << times[k];
        EXPECT_EQ(frame.cells, mesh.cells);
    }
    // The case written is now an input: its points may not be an output.
    EXPECT_THROW(check_openfoam_frame_outputs(out, {"constant"}, input, mesh_input_files(out)), UsageError);
}

TEST(OpenFoamFrames, AMeshOfAnotherFormatIsWrittenWholeOnce) {
    const Mesh mesh = read_mesh(openfoam_case("cavity"));
    const fs::path out = scratch_dir() / "from-su2";
    write_openfoam_frame_base(out, "0", mesh, MeshExtras{});
    write_openfoam_frame_points(out, "0", mesh.points, MeshExtras{});
    const Mesh back = read_mesh(out / "0");
    EXPECT_EQ(back.points, mesh.points);
    EXPECT_EQ(back.cells.size(), mesh.cells.size());
}

TEST(MeshFormatFiles, AnOpenFoamCaseReadsAndWritesItsPolyMeshFiles) {
    const fs::path input = openfoam_case("cavity");
    const std::vector<fs::path> read = mesh_input_files(input);
    ASSERT_EQ(read.size(), std::size(poly_mesh_file_names));
    for (const fs::path& f : read) EXPECT_TRUE(fs::exists(f)) << f;
    EXPECT_EQ(read.front().filename(), "points");
    // A decomposed case: each processor's polyMesh and addressing files.
    const std::vector<fs::path> decomposed = mesh_input_files(openfoam_case("mixed-decomposed"));
    EXPECT_EQ(decomposed.size(), 2 * (std::size(poly_mesh_file_names) + std::size(processor_addressing_file_names)));
    for (const fs::path& f : decomposed) EXPECT_TRUE(fs::exists(f)) << f;
    // A file format: the file itself, checked as one file.
    EXPECT_EQ(mesh_input_files("a/b.su2"), std::vector<fs::path>{"a/b.su2"});
    // Writing into the input case is writing over its files.
    EXPECT_THROW(check_mesh_output(input, read), UsageError);
    EXPECT_NO_THROW(check_mesh_output(scratch_dir() / "new-case/", read));
    const fs::path su2 = scratch_dir() / "m.su2";
    write_su2(su2, read_mesh(input));
    EXPECT_THROW(check_mesh_output(su2, {su2}), UsageError);
    EXPECT_NO_THROW(check_mesh_output(su2, read));
}
