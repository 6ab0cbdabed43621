// The symmetry markers of an SU2 configuration file (io/su2/su2_config.hpp).
#include "dgwarp/io/su2/su2_config.hpp"

#include <gtest/gtest.h>

#include "dgwarp/core/error.hpp"
#include "support/test_paths.hpp"

namespace dgwarp {
namespace {

TEST(Su2Config, MarkerSymListsItsMarkersWithTheirLines) {
    const auto dir = test::scratch_dir();
    const auto cfg = test::write_text(dir / "case.cfg",
                                      "% SU2 configuration\n"
                                      "SOLVER= EULER\n"
                                      "MARKER_EULER= ( airfoil )\n"
                                      "marker_sym= ( left,right ) % both sides\n"
                                      "% MARKER_SYM= ( commented )\n"
                                      "MARKER_SYM = bottom\r\n"
                                      "MARKER_SYM= NONE\n");
    const std::vector<Su2ConfigMarker> m = su2_symmetry_markers(cfg);
    ASSERT_EQ(m.size(), 3u);
    EXPECT_EQ(m[0].name, "left");
    EXPECT_EQ(m[0].line, 4u);
    EXPECT_EQ(m[1].name, "right");
    EXPECT_EQ(m[2].name, "bottom");
    EXPECT_EQ(m[2].line, 6u);
    EXPECT_TRUE(su2_symmetry_markers(test::write_text(dir / "none.cfg", "MARKER_SYM= ( )\n")).empty());
}

TEST(Su2Config, AnUnclosedListAndAMissingFileAreErrors) {
    const auto dir = test::scratch_dir();
    try {
        su2_symmetry_markers(test::write_text(dir / "bad.cfg", "\nMARKER_SYM= ( left, right\n"));
        ADD_FAILURE() << "no error";
    } catch (const ParseError& e) {
        EXPECT_EQ(e.line(), 2u);
        EXPECT_NE(std::string(e.what()).find("bad.cfg"), std::string::npos) << e.what();
    }
    EXPECT_THROW(su2_symmetry_markers(dir / "missing.cfg"), IoError);
}

}  // namespace
}  // namespace dgwarp
