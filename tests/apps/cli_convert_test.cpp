// `dgwarp convert` end to end: SU2 -> SU2, SU2 -> msh -> SU2 on the real meshes.
#include <gtest/gtest.h>

#include "dgwarp/io/mesh_io.hpp"
#include "support/test_paths.hpp"

using namespace dgwarp;
using namespace dgwarp::test;

namespace {
}  // namespace

TEST(CliConvert, RoundTripsThroughEveryFormatAreExactOnRealMeshes) {
    DGWARP_REQUIRE_SHARED_MESHES();
    const auto meshes = su2_meshes();
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

// #17 item 6: the second zone of SU2's chtPinArray and the FFD box of its
// bricks pass through deform and convert to SU2, and other formats say what
// they cannot hold.
TEST(CliConvert, OtherZonesAndFfdBoxesPassThroughSu2AndAreNamedWhenDropped) {
    DGWARP_REQUIRE_SHARED_MESHES();
    const auto dir = dgwarp::test::scratch_dir();
    const auto cht = dgwarp::test::su2_meshes_dir() / "incomp_navierstokes_streamwise_periodic_chtPinArray_3d_3D_chtPinArray_coarse.su2";
    const auto motion = dgwarp::test::write_text(dir / "pin.json", R"({"markers": {"fluid_pin1": {"translate": [1e-5, 0, 0]}}})");
    const std::string base = "deform " + quoted(cht) + " -m " + quoted(motion) + " -o ";
    ASSERT_EQ(run_cli(base + quoted(dir / "out.su2") + " -q").exit_code, 0);
    const std::string in = slurp(cht), out = slurp(dir / "out.su2");
    const auto zone2 = in.find("IZONE= 2");
    ASSERT_NE(zone2, std::string::npos);
    ASSERT_NE(out.find("IZONE= 2"), std::string::npos);
    EXPECT_EQ(out.substr(out.find("IZONE= 2")), in.substr(zone2));  // zone 2 byte for byte
    EXPECT_NE(out, in);                                               // zone 1 moved
    CommandResult r = run_cli(base + quoted(dir / "out.vtu"));
    EXPECT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(r.err.find("also has 1 other zone (IZONE=) (an .su2 output keeps them)"), std::string::npos) << r.err;

    const auto brick = dgwarp::test::su2_meshes_dir() / "deformation_brick_hex_mesh_brick_hex_ffd.su2";
    r = run_cli("convert " + quoted(brick) + " " + quoted(dir / "brick.su2"));
    EXPECT_EQ(r.exit_code, 0) << r.err;
    EXPECT_EQ(r.err.find("warning"), std::string::npos) << r.err;
    const std::string brick_in = slurp(brick), brick_out = slurp(dir / "brick.su2");
    EXPECT_EQ(brick_out.substr(brick_out.find("NPERIODIC=")), brick_in.substr(brick_in.find("NPERIODIC=")));
    r = run_cli("convert " + quoted(brick) + " " + quoted(dir / "brick.msh"));
    EXPECT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(r.err.find("NPERIODIC= 1, FFD_NBOX= 1"), std::string::npos) << r.err;
}

// #17 item 10: info, quality, picture and convert read the VTU deform writes.
TEST(CliConvert, TheVtuDeformWritesIsReadByInfoQualityPictureAndConvert) {
    const auto dir = dgwarp::test::scratch_dir();
    ASSERT_EQ(run_cli("case rect-box -q -o " + quoted(dir / "rb.su2") + " --motions " + quoted(dir / "m")).exit_code, 0);
    ASSERT_EQ(run_cli("deform " + quoted(dir / "rb.su2") + " -m " + quoted(dir / "m" / "rotate-30.json") + " -q -o " +
                      quoted(dir / "out.vtu"))
                  .exit_code,
              0);
    CommandResult r = run_cli("info " + quoted(dir / "out.vtu") + " --json");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(r.out.find("\"rectangle\""), std::string::npos) << r.out;  // the markers came back
    r = run_cli("quality " + quoted(dir / "out.vtu") + " --reference " + quoted(dir / "rb.su2"));
    EXPECT_EQ(r.exit_code, 0) << r.err;
    r = run_cli("picture " + quoted(dir / "out.vtu") + " -o " + quoted(dir / "out.png") + " -q");
    EXPECT_EQ(r.exit_code, 0) << r.err;
    EXPECT_TRUE(std::filesystem::exists(dir / "out.png"));
    r = run_cli("convert " + quoted(dir / "out.vtu") + " " + quoted(dir / "back.su2") + " -q");
    EXPECT_EQ(r.exit_code, 0) << r.err;
    r = run_cli("deform " + quoted(dir / "rb.su2") + " -m " + quoted(dir / "m" / "rotate-30.json") + " -q -o " +
                quoted(dir / "direct.su2"));
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_EQ(slurp(dir / "back.su2"), slurp(dir / "direct.su2"));  // through VTU, bit for bit
}
