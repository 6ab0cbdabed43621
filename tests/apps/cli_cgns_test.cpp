// `dgwarp convert` and `dgwarp deform` on CGNS files, end to end: round trips
// through every format, deform writing a copy of the input with new
// coordinates, damaged files refused with nothing written.
#include <gtest/gtest.h>

#include "dgwarp/io/cgns/cgns.hpp"
#include "dgwarp/io/mesh_io.hpp"
#include "support/cgns_test_writer.hpp"

using namespace dgwarp;
using namespace dgwarp::test;

namespace {

const char* cgns_lift_motion = R"({"markers": {"UserDefined 2": {"translate": [0, 0, 0.05]}}, "default": "fixed",
                                   "shared_nodes": "moving_wins"})";

}  // namespace

// CGNS to every format and back, and every format to CGNS and back: the same
// mesh (coordinates bit for bit, cells, markers). OpenFOAM turns cells to
// its reader's node order, so its round trips start from an OpenFOAM mesh.
TEST(CliCgns, ConvertRoundTripsThroughEveryFormatExactly) {
    const auto dir = scratch_dir();
    for (const std::string name : {"mixed.cgns", "mixed-adf.cgns"}) {
        const auto input = cgns_data(name);
        const Mesh original = read_mesh(input);
        for (const std::string ext : {".su2", ".msh", ".vtu"}) {
            const auto file = dir / ("mesh" + ext), back = dir / "back.cgns";
            ASSERT_EQ(run_cli("convert -q " + quoted(input) + " " + quoted(file)).exit_code, 0) << ext;
            EXPECT_TRUE(read_mesh(file) == original) << name << ext;
            ASSERT_EQ(run_cli("convert -q " + quoted(file) + " " + quoted(back)).exit_code, 0) << ext;
            EXPECT_TRUE(read_mesh(back) == original) << name << ext << " back to CGNS";
        }
        const auto msh22 = dir / "mesh22.msh";
        ASSERT_EQ(run_cli("convert -q --gmsh-version 22 " + quoted(input) + " " + quoted(msh22)).exit_code, 0);
        EXPECT_TRUE(read_mesh(msh22) == original);
        // CGNS to CGNS: a copy of the input (its coordinates are the mesh's).
        ASSERT_EQ(run_cli("convert -q " + quoted(input) + " " + quoted(dir / "copy.cgns")).exit_code, 0);
        EXPECT_TRUE(read_mesh(dir / "copy.cgns") == original);
        // aflr3_to_cgns's BC names ("UserDefined 1") cannot name OpenFOAM patches: written with '_'
        // (and said, without -q: CliOpenFoam.CgnsNamesWithBlanksBecomePatchNames).
        const CommandResult r = run_cli("convert -q " + quoted(input) + " " + quoted(dir / (name + "-case/")));
        EXPECT_EQ(r.exit_code, 0) << r.err;
        const Mesh foam = read_mesh(dir / (name + "-case"));
        ASSERT_EQ(foam.markers.size(), original.markers.size());
        EXPECT_EQ(foam.markers[0].name, "UserDefined_1");
        EXPECT_EQ(foam.points, original.points);
    }
    // An OpenFOAM case through CGNS and back (CGNS to OpenFOAM gives the
    // OpenFOAM reader's cell node order, so the round trip starts there), and a 2D SU2 mesh.
    const auto foam_case = source_dir() / "tests/data/openfoam/mixed";
    const Mesh foam = read_mesh(foam_case);
    ASSERT_EQ(run_cli("convert -q " + quoted(foam_case) + " " + quoted(dir / "foam.cgns")).exit_code, 0);
    EXPECT_TRUE(read_mesh(dir / "foam.cgns") == foam);
    ASSERT_EQ(run_cli("convert -q " + quoted(dir / "foam.cgns") + " " + quoted(dir / "foam-again/")).exit_code, 0);
    EXPECT_TRUE(read_mesh(dir / "foam-again") == foam);
    ASSERT_EQ(run_cli("case rect-box -q -o " + quoted(dir / "rb.su2")).exit_code, 0);
    ASSERT_EQ(run_cli("convert -q " + quoted(dir / "rb.su2") + " " + quoted(dir / "rb.cgns")).exit_code, 0);
    ASSERT_EQ(run_cli("convert -q " + quoted(dir / "rb.cgns") + " " + quoted(dir / "rb-back.su2")).exit_code, 0);
    EXPECT_EQ(slurp(dir / "rb-back.su2"), slurp(dir / "rb.su2"));
}

// deform mesh.cgns -o out.cgns: a copy of the input with the moved points
// (those an SU2 output gets), everything else as it was.
TEST(CliCgns, DeformWritesACopyOfTheInputWithTheMovedPoints) {
    const auto dir = scratch_dir();
    const auto motion = write_text(dir / "lift.json", cgns_lift_motion);
    const auto input = cgns_data("mixed.cgns");
    const std::string base = "deform -q " + quoted(input) + " -m " + quoted(motion) + " -o ";
    ASSERT_EQ(run_cli(base + quoted(dir / "out.cgns")).exit_code, 0);
    ASSERT_EQ(run_cli(base + quoted(dir / "out.su2")).exit_code, 0);
    const Mesh original = read_mesh(input), moved = read_mesh(dir / "out.cgns");
    EXPECT_EQ(moved.points, read_mesh(dir / "out.su2").points);
    EXPECT_NE(moved.points, original.points);
    EXPECT_EQ(moved.cells, original.cells);
    EXPECT_EQ(moved.markers, original.markers);
    if (run_command("command -v cgnsdiff").exit_code == 0) {
        const CommandResult r = run_command("cgnsdiff -d " + quoted(input) + " " + quoted(dir / "out.cgns"));
        EXPECT_EQ(r.out.find("CoordinateX"), std::string::npos) << r.out;  // x does not move
        EXPECT_NE(r.out.find("CoordinateZ"), std::string::npos) << r.out;
        EXPECT_EQ(r.out.find("Elements"), std::string::npos) << r.out;
        EXPECT_EQ(r.out.find("BC"), std::string::npos) << r.out;
    }
    // The input is no output.
    const CommandResult r = run_cli("deform " + quoted(input) + " -m " + quoted(motion) + " -o " + quoted(input));
    EXPECT_EQ(r.exit_code, 1) << r.err;
}

// Prefixes of a valid file: exit 2 with the file named, nothing written.
TEST(CliCgns, DamagedFilesExitWith2AndWriteNothing) {
    const auto dir = scratch_dir();
    const auto motion = write_text(dir / "lift.json", cgns_lift_motion);
    const std::string bytes = slurp(cgns_data("mixed.cgns"));
    const auto cut = dir / "cut.cgns";
    for (std::size_t n = 0; n < bytes.size(); n += bytes.size() / 7) {
        write_text(cut, bytes.substr(0, n));
        for (const std::string& args : {"convert " + quoted(cut) + " " + quoted(dir / "out.su2"),
                                        "convert " + quoted(cut) + " " + quoted(dir / "out.cgns"),
                                        "deform " + quoted(cut) + " -m " + quoted(motion) + " -o " + quoted(dir / "out.cgns")}) {
            const CommandResult r = run_cli(args);
            EXPECT_EQ(r.exit_code, 2) << args << " cut at " << n << "\n" << r.err;
            EXPECT_NE(r.err.find(cut.string()), std::string::npos) << r.err;
            EXPECT_EQ(r.err.find("HDF5"), std::string::npos) << r.err;  // no library noise
        }
        EXPECT_FALSE(std::filesystem::exists(dir / "out.su2"));
        EXPECT_FALSE(std::filesystem::exists(dir / "out.cgns"));
    }
    EXPECT_EQ(std::distance(std::filesystem::directory_iterator(dir), std::filesystem::directory_iterator()), 2);
}

// The ADF file on which libcgns 3.4 wrote into freed memory (a GridLocation
// of data type "c1"): refused before libcgns reads it, exit 2 naming the file and the node.
TEST(CliCgns, AFileLibcgnsWouldCrashOnExitsWith2NamingTheNode) {
    const auto file = source_dir() / "tests" / "data" / "fuzz_regressions" / "cgns" / "adf-bc-gridlocation-type-c1.cgns";
    const CommandResult r = run_cli("info " + quoted(file));
    EXPECT_EQ(r.exit_code, 2) << r.err;
    EXPECT_NE(r.err.find(file.string() + ": cannot open as a CGNS file: it is damaged (/Base/Zone/ZoneBC/UserDefined "
                                          "5/GridLocation: data of type 'c1'"),
              std::string::npos)
        << r.err;
}
