// Sliding markers from the command line: named "slide" in the motion, or
// made to slide by an SU2 configuration's MARKER_SYM (--su2-config).
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "dgwarp/io/mesh_io.hpp"
#include "support/test_paths.hpp"

using namespace dgwarp;
using namespace dgwarp::test;

namespace {

const char* brick_squeeze = R"({"markers": {"z_p": {"translate": [0, 0, -0.1]}}})";

}  // namespace

TEST(CliSliding, Su2ConfigSymmetryMarkersSlideAsIfNamed) {
    DGWARP_REQUIRE_SHARED_MESHES();
    const auto dir = scratch_dir();
    const auto brick = su2_meshes_dir() / "deformation_brick_hex_mesh_brick_hex_ffd.su2";
    const auto squeeze = write_text(dir / "squeeze.json", brick_squeeze);
    const auto cfg = write_text(dir / "brick.cfg", "MARKER_SYM= ( x_m, x_p )\nMARKER_SYM= ( y_m, y_p )\n");
    const CommandResult typed = run_cli("deform " + quoted(brick) + " -m " + quoted(squeeze) + " --su2-config " +
                                        quoted(cfg) + " -o " + quoted(dir / "typed.su2") + " --json");
    ASSERT_EQ(typed.exit_code, 0) << typed.err;
    const nlohmann::json report = nlohmann::json::parse(typed.out);
    EXPECT_EQ(report["boundary"]["sliding_by_type"], nlohmann::json::array({"x_m", "x_p", "y_m", "y_p"}));
    EXPECT_EQ(report["frames"][0]["quality"]["inverted"], 0);
    // The same as naming them "slide", byte for byte.
    const auto named = write_text(dir / "named.json", R"({"markers": {"z_p": {"translate": [0, 0, -0.1]},
        "x_m": "slide", "x_p": "slide", "y_m": "slide", "y_p": "slide"}})");
    ASSERT_EQ(run_cli("deform -q " + quoted(brick) + " -m " + quoted(named) + " -o " + quoted(dir / "named.su2")).exit_code, 0);
    EXPECT_EQ(slurp(dir / "typed.su2"), slurp(dir / "named.su2"));
    // Each side's nodes stay in its plane.
    const Mesh before = read_mesh(brick), after = read_mesh(dir / "typed.su2");
    for (const auto& [marker, axis] : {std::pair{"x_m", 0}, {"x_p", 0}, {"y_m", 1}, {"y_p", 1}})
        for (NodeId v : marker_nodes(find_marker(before, marker)))
            EXPECT_EQ(after.points[3 * static_cast<std::size_t>(v) + axis], before.points[3 * static_cast<std::size_t>(v) + axis])
                << marker << " node " << v;

    // A default in the motion says what the unnamed markers do: nothing slides.
    const auto held = write_text(dir / "held.json", R"({"markers": {"z_p": {"translate": [0, 0, -0.1]}}, "default": "fixed"})");
    const CommandResult fixed = run_cli("check " + quoted(brick) + " -m " + quoted(held) + " --su2-config " + quoted(cfg) + " --json");
    ASSERT_EQ(fixed.exit_code, 0) << fixed.err;
    EXPECT_EQ(nlohmann::json::parse(fixed.out)["boundary"]["sliding_by_type"], nlohmann::json::array());
}

TEST(CliSliding, AConfigNamingAnUnknownMarkerIsAnErrorNamingItsLine) {
    DGWARP_REQUIRE_SHARED_MESHES();
    const auto dir = scratch_dir();
    const auto brick = su2_meshes_dir() / "deformation_brick_hex_mesh_brick_hex_ffd.su2";
    const auto squeeze = write_text(dir / "squeeze.json", brick_squeeze);
    const auto cfg = write_text(dir / "brick.cfg", "% sides\n\nMARKER_SYM= ( x_m, symmetry )\n");
    const CommandResult r = run_cli("deform " + quoted(brick) + " -m " + quoted(squeeze) + " --su2-config " + quoted(cfg) +
                                    " -o " + quoted(dir / "out.su2"));
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_NE(r.err.find("brick.cfg:3: MARKER_SYM: unknown marker 'symmetry'"), std::string::npos) << r.err;
    EXPECT_FALSE(std::filesystem::exists(dir / "out.su2"));
}
