// `dgwarp convert` end to end: SU2 -> SU2, SU2 -> msh -> SU2 on the real meshes.
#include <gtest/gtest.h>

#include "dgwarp/io/mesh_io.hpp"
#include "support/test_paths.hpp"

using namespace dgwarp;
using namespace dgwarp::test;

namespace {
}  // namespace

TEST(CliConvert, RoundTripsThroughEveryFormatAreExactOnRealMeshes) {
    const auto meshes = su2_meshes();
    if (meshes.empty()) GTEST_SKIP() << "no ../shared/meshes/su2";
    const auto dir = scratch_dir();
    for (const auto& path : meshes) {
        const Mesh original = read_mesh(path);
        for (const char* version : {"41", "22"}) {
            const auto msh = dir / "mesh.msh", su2 = dir / "mesh.su2";
            ASSERT_EQ(run_cli("convert -q " + quoted(path) + " " + quoted(msh) + " --gmsh-version " + version).exit_code, 0)
                << path;
            ASSERT_EQ(run_cli("convert -q " + quoted(msh) + " " + quoted(su2)).exit_code, 0) << path;
            EXPECT_TRUE(read_mesh(su2) == original) << path << " via msh " << version;
        }
        const auto vtu = dir / "mesh.vtu";
        EXPECT_EQ(run_cli("convert -q " + quoted(path) + " " + quoted(vtu)).exit_code, 0) << path;
    }
}
