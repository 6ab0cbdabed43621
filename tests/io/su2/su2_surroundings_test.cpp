// What an SU2 file holds around the zone read (other zones, FFD boxes,
// periodic data, comments) passes through a deformed copy unchanged
// (#17 item 6: a two-zone file lost its second zone, the bricks their FFD box).
#include <gtest/gtest.h>

#include <string>

#include "dgwarp/core/error.hpp"
#include "dgwarp/io/mesh_io.hpp"
#include "dgwarp/io/su2/su2.hpp"
#include "support/test_paths.hpp"

using namespace dgwarp;

namespace {

// One triangle zone: `x` shifts its points so the zones differ.
std::string surroundings_zone(const std::string& x, bool with_ndime) {
    return std::string(with_ndime ? "NDIME= 2\n" : "") +
           "NELEM= 1\n5 0 1 2 0\nNPOIN= 3\n" + x + " 0 0\n1 0 1\n0 1 2\nNMARK= 1\nMARKER_TAG= wall\nMARKER_ELEMS= 1\n3 0 1\n";
}

const std::string ffd_tail =
    "NPERIODIC= 1\nPERIODIC_INDEX= 0\n0.0 0.0 0.0\n"
    "FFD_NBOX= 1\nFFD_NLEVEL= 1\nFFD_TAG= MAIN_BOX\nFFD_SURFACE_POINTS= 1\nwall 0 0.5 0.5 0.0\n";

/// Writes `text` to a scratch file, reads zone `zone` with its surroundings,
/// moves every point by 0.25 in x and writes it back with them; returns the result's text.
std::string deformed_copy(const std::string& text, int zone, Su2Surroundings& s, Mesh& mesh) {
    const auto dir = test::scratch_dir();
    const auto in = test::write_text(dir / "in.su2", text);
    mesh = read_su2(in, zone, {}, s);
    for (std::size_t i = 0; i < mesh.points.size(); i += 2) mesh.points[i] += 0.25;
    write_su2(dir / "out.su2", mesh, s);
    return test::slurp(dir / "out.su2");
}

}  // namespace

TEST(Su2Surroundings, FfdBoxesPeriodicDataAndCommentsPassThrough) {
    const std::string text = "% made by hand\n" + surroundings_zone("0", true) + ffd_tail;
    Su2Surroundings s;
    Mesh moved;
    const std::string out = deformed_copy(text, 1, s, moved);
    EXPECT_EQ(s.before, "% made by hand\n");
    EXPECT_EQ(s.after, ffd_tail);
    EXPECT_EQ(s.contents, (std::vector<std::string>{"NPERIODIC= 1", "FFD_NBOX= 1"}));
    EXPECT_TRUE(out.starts_with("% made by hand\nNDIME= 2\n")) << out;
    EXPECT_TRUE(out.ends_with(ffd_tail)) << out;
    EXPECT_EQ(read_su2_text("out.su2", out), moved);
}

TEST(Su2Surroundings, TheOtherZonesOfAMultiZoneFileAreKeptByteForByte) {
    const std::string zone1 = surroundings_zone("0", true), zone2 = surroundings_zone("5", true);
    const std::string text = "NZONE= 2\n\nIZONE= 1\n" + zone1 + "\nIZONE= 2\n" + zone2 + ffd_tail;
    for (int zone : {1, 2}) {
        SCOPED_TRACE(zone);
        Su2Surroundings s;
        Mesh moved;
        const std::string out = deformed_copy(text, zone, s, moved);
        EXPECT_EQ(s.contents.front(), "1 other zone (IZONE=)");
        EXPECT_EQ(read_su2_text("out.su2", out, zone), moved);
        const int other = 3 - zone;
        EXPECT_EQ(read_su2_text("out.su2", out, other), read_su2_text("in.su2", text, other));
        EXPECT_TRUE(out.ends_with(ffd_tail));
        if (zone == 2) {
            EXPECT_TRUE(out.starts_with("NZONE= 2\n\nIZONE= 1\n" + zone1 + "\nIZONE= 2\n"));
        }
    }
}

TEST(Su2Surroundings, AZoneWithoutItsOwnNdimeIsWrittenWithoutOne) {
    // The dimension given once, before NZONE= (a form the reader accepts).
    const std::string text = "NDIME= 2\nNZONE= 2\nIZONE= 1\n" + surroundings_zone("0", false) + "IZONE= 2\n" +
                             surroundings_zone("5", false);
    Su2Surroundings s;
    Mesh moved;
    const std::string out = deformed_copy(text, 2, s, moved);
    EXPECT_FALSE(s.zone_has_ndime);
    EXPECT_EQ(out.find("NDIME", 1), std::string::npos) << out;  // only the header's
    EXPECT_EQ(read_su2_text("out.su2", out, 2), moved);
    EXPECT_EQ(read_su2_text("out.su2", out, 1), read_su2_text("in.su2", text, 1));
}

TEST(Su2Surroundings, AnotherMeshIsRefusedBeforeWriting) {
    const auto dir = test::scratch_dir();
    const auto in = test::write_text(dir / "in.su2", surroundings_zone("0", true) + ffd_tail);
    Su2Surroundings s;
    Mesh mesh = read_su2(in, 1, {}, s);
    mesh.points.insert(mesh.points.end(), {2.0, 2.0});
    EXPECT_THROW(write_su2(dir / "out.su2", mesh, s), MeshError);
    EXPECT_FALSE(std::filesystem::exists(dir / "out.su2"));
}

TEST(Su2Surroundings, WriteMeshKeepsThemForSu2AndSaysWhatOtherFormatsDrop) {
    const auto dir = test::scratch_dir();
    const auto in = test::write_text(dir / "in.su2", surroundings_zone("0", true) + ffd_tail);
    MeshExtras extras;
    const Mesh mesh = read_mesh(in, {}, {}, extras);
    ASSERT_TRUE(extras.su2.has_value());
    WriteOptions options;
    options.extras = &extras;
    write_mesh(dir / "out.su2", mesh, {}, options);
    const std::string out = test::slurp(dir / "out.su2");
    EXPECT_TRUE(out.ends_with(ffd_tail)) << out;
    EXPECT_EQ(read_su2_text("out.su2", out), mesh);
    EXPECT_TRUE(dropped_extras(extras, dir / "out.su2").empty());
    EXPECT_EQ(dropped_extras(extras, dir / "out.vtu"), (std::vector<std::string>{"NPERIODIC= 1", "FFD_NBOX= 1"}));
    EXPECT_EQ(dropped_extras(extras, dir / "out.msh").size(), 2u);
    EXPECT_EQ(dropped_extras_warning(extras, "in.su2", "out.vtu"),
              "out.vtu holds the mesh only: in.su2 also has NPERIODIC= 1, FFD_NBOX= 1 (an .su2 output keeps them)");
    EXPECT_EQ(dropped_extras_warning(extras, "in.su2", "out.su2"), "");
}
