// A job's frames written (job/frame_outputs.hpp): the names of a series, the
// fields a VTU frame carries, and a 2D case's frames in 3D, read back.
#include "dgwarp/job/frame_outputs.hpp"

#include <gtest/gtest.h>

#include <fstream>

#include "dgwarp/io/motion_file.hpp"
#include "dgwarp/quality/mesh_quality.hpp"
#include "io/openfoam/openfoam_test_support.hpp"

using namespace dgwarp;
using namespace dgwarp::test;
namespace fs = std::filesystem;

TEST(FrameOutputs, ASeriesIsNumberedWithAtLeastFourDigits) {
    EXPECT_EQ(frame_path("out/m.vtu", 0, 1), "out/m.vtu");
    EXPECT_EQ(frame_path("out/m.vtu", 3, 12), "out/m_0003.vtu");
    EXPECT_EQ(frame_path("m.su2", 12345, 20000), "m_12345.su2");
    EXPECT_EQ(frame_path("m.su2", 7, 10000), "m_0007.su2");     // the last frame is 9999
    EXPECT_EQ(frame_path("m.su2", 7, 10001), "m_00007.su2");    // the last frame is 10000: 5 digits
    EXPECT_EQ(frame_path("m.su2", 7, 100001), "m_000007.su2");  // 100000: 6
    const fs::path dir = scratch_dir();
    for (int k = 0; k < 4; ++k) std::ofstream(frame_path(dir / "m.vtu", k, 4)) << "x";
    EXPECT_EQ(stale_frames(dir / "m.vtu", 2), (std::vector<fs::path>{dir / "m_0002.vtu", dir / "m_0003.vtu"}));
    EXPECT_TRUE(stale_frames(dir / "m.vtu", 4).empty());
    EXPECT_EQ(stale_frames(dir / "m.vtu", 1).size(), 4u);  // one frame is written to m.vtu itself
}

TEST(FrameOutputs, DisplacementHasThreeComponentsAlsoIn2d) {
    Mesh mesh;
    mesh.dim = 2;
    mesh.points = {0, 0, 1, 0, 0, 1};
    const std::vector<double> moved = {0.5, 0, 1, 0.25, 0, 1};
    const MeshFields f = deformation_fields(mesh, moved, {0.9}, {});
    ASSERT_EQ(f.point_data.size(), 1u);
    EXPECT_EQ(f.point_data[0].name, "displacement");
    EXPECT_EQ(f.point_data[0].values, (std::vector<double>{0.5, 0, 0, 0, 0.25, 0, 0, 0, 0}));
    ASSERT_EQ(f.cell_data.size(), 1u);  // no ratio given
    EXPECT_EQ(f.cell_data[0].values, std::vector<double>{0.9});
    EXPECT_EQ(deformation_fields(mesh, moved, {0.9}, {0.95}).cell_data.at(1).name, "quality_ratio");
}

TEST(FrameOutputs, A2dCasesFramesAreWrittenIn3dAsFilesAndAsTimeFolders) {
    JobInputs in;
    in.mesh = read_mesh(openfoam_case("cavity"), {}, {}, in.extras);
    in.spec = parse_motion_file(R"({"markers": {"movingWall": {"translate": [0.001, 0, 0]}}})", "m.json",
                                fs::temp_directory_path());
    classify_inputs(in, {});
    ASSERT_TRUE(in.planar);
    measure_original_cells(in, [] {});
    std::vector<double> points = in.mesh.points;
    for (std::size_t i = 0; i < points.size(); i += 2) points[i] *= 1.001;
    const std::vector<double> given = points;
    const std::vector<double> quality = cell_qualities(in.mesh, points, in.original.orientation);
    const fs::path dir = scratch_dir();

    FrameOutputs files{dir / "m.vtu", 2};
    EXPECT_EQ(write_frame(in, files, 1, points, quality), dir / "m_0001.vtu");
    EXPECT_EQ(points, given);
    const Mesh vtu = read_mesh(dir / "m_0001.vtu");
    EXPECT_EQ(vtu.dim, 3);
    EXPECT_EQ(vtu.num_points(), in.file_mesh.num_points());

    const std::vector<std::string> times = {"0.5"};
    FrameOutputs foam{dir / "case", 1, times};
    EXPECT_EQ(write_frame(in, foam, 0, points, quality), dir / "case/0.5/polyMesh/points");
    EXPECT_TRUE(foam.base_written);
    const Mesh back = read_mesh(dir / "case/0.5");
    EXPECT_EQ(back.points, vtu.points);  // the same 3D points either way
    std::vector<double> buffer;
    const auto lifted = output_points(in, std::span<const double>(given), buffer);
    EXPECT_TRUE(std::equal(lifted.begin(), lifted.end(), back.points.begin()));
}

TEST(FrameOutputs, TheFramesOfAnEarlierLongerSeriesAreAWarningWithTheirCount) {
    const fs::path dir = scratch_dir();
    EXPECT_FALSE(stale_frames_warning(dir / "m.vtu", 2));
    for (int k = 0; k < 5; ++k) std::ofstream(frame_path(dir / "m.vtu", k, 5)) << "x";
    const auto w = stale_frames_warning(dir / "m.vtu", 3);
    ASSERT_TRUE(w);
    EXPECT_EQ(w->code, WarningCode::stale_frames);
    EXPECT_EQ(w->count, 2);
    EXPECT_EQ(w->text, (dir / "m_0003.vtu").string() + " ... " + (dir / "m_0004.vtu").string() +
                           " (2 files) are left from an earlier run, not written by this one (3 frames); remove them "
                           "if they are not wanted");
    EXPECT_FALSE(stale_frames_warning(dir / "m.vtu", 5));
}

TEST(FrameOutputs, ADecomposedCaseReadWholeSaysItsProcessorFoldersStayAsTheyWere) {
    const fs::path dir = scratch_dir();
    const fs::path c = dir / "case";
    fs::copy(openfoam_case("mixed"), c, fs::copy_options::recursive);
    EXPECT_FALSE(unread_processors_warning(c.string(), false));  // no processor folder
    for (const char* p : {"processor0", "processor1"})
        fs::copy(openfoam_case("mixed-decomposed") / p, c / p, fs::copy_options::recursive);
    const auto w = unread_processors_warning(c.string(), false);
    ASSERT_TRUE(w);
    EXPECT_EQ(w->code, WarningCode::processors_unchanged);
    EXPECT_EQ(w->count, 2);
    EXPECT_NE(w->text.find("holds constant/polyMesh and 2 processor folders (processor0 ... processor1)"),
              std::string::npos)
        << w->text;
    EXPECT_FALSE(unread_processors_warning(c.string(), true));  // written with the whole case
    EXPECT_FALSE(unread_processors_warning((dir / "m.su2").string(), false));
}
