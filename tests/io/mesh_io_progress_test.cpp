// read_mesh reports how much of the file it has parsed, and the callback
// changes nothing in the mesh it reads.
#include <gtest/gtest.h>

#include "dgwarp/io/mesh_io.hpp"
#include "support/progress_recorder.hpp"
#include "support/test_paths.hpp"

using namespace dgwarp;

TEST(ReadMeshProgress, Su2FileReportsPerMegabyteAndEndsAtOne) {
    DGWARP_REQUIRE_SHARED_MESHES();
    const auto file = test::su2_meshes_dir() / "deformation_brick_pyra_mesh_brick_pyra_ffd.su2";  // 3.3 MB
    test::ProgressRecorder rec;
    const Mesh with = read_mesh(file, {}, rec.fn());
    // 0, then after about each MiB (3 of them), then 1.
    rec.expect_complete(5);
    EXPECT_EQ(rec.fractions().front(), 0.0);
    EXPECT_LE(rec.fractions().size(), 6u);
    EXPECT_EQ(with, read_mesh(file));
}

TEST(ReadMeshProgress, GmshFileEndsAtOne) {
    DGWARP_REQUIRE_SHARED_MESHES();
    const Mesh mesh = read_mesh(test::su2_meshes_dir() / "deformation_naca0012_mesh_NACA0012_inv.su2");
    const auto file = test::scratch_dir() / "naca.msh";
    write_mesh(file, mesh);
    test::ProgressRecorder rec;
    const Mesh back = read_mesh(file, {}, rec.fn());
    rec.expect_complete(2);  // a small file: the start and the end
    EXPECT_EQ(back, read_mesh(file));
}
