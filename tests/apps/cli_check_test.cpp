// `dgwarp check MESH -m MOTION`: what deform checks, for every frame, without deforming.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "support/rect_box_files.hpp"
#include "support/test_paths.hpp"

using namespace dgwarp::test;

namespace {

bool check_cli_has(const std::string& s, const std::string& part) { return s.find(part) != std::string::npos; }

/// A unit square of two triangles whose markers "left" (nodes 3, 0) and
/// "bottom" (nodes 0, 1) share node 0.
std::filesystem::path check_cli_square(const std::filesystem::path& dir) {
    return write_text(dir / "square.su2", R"(NDIME= 2
NELEM= 2
5 0 1 2 0
5 0 2 3 1
NPOIN= 4
0 0 0
1 0 1
1 1 2
0 1 3
NMARK= 2
MARKER_TAG= left
MARKER_ELEMS= 1
3 3 0
MARKER_TAG= bottom
MARKER_ELEMS= 1
3 0 1
)");
}

std::size_t check_cli_file_count(const std::filesystem::path& dir) {
    return static_cast<std::size_t>(std::distance(std::filesystem::directory_iterator(dir), {}));
}

}  // namespace

TEST(CheckCli, AGoodMotionPrintsDeformsSummaryAndWritesNothing) {
    const RectBoxFiles c = rect_box_files();
    const std::size_t files = check_cli_file_count(c.dir);
    const CommandResult r = run_cli("check " + quoted(c.mesh) + " -m " + quoted(c.motion));
    ASSERT_EQ(r.exit_code, 0) << r.err;
    // The summary lines deform prints, then the verdict.
    const CommandResult d = run_cli("deform " + quoted(c.mesh) + " -m " + quoted(c.motion) + " -o " +
                                    quoted(c.dir / "out.su2"));
    ASSERT_EQ(d.exit_code, 0) << d.err;
    for (const std::string line : {"mesh      ", "motion    ", "boundary  "}) {
        const std::size_t at = d.out.find(line);
        ASSERT_NE(at, std::string::npos) << d.out;
        EXPECT_TRUE(check_cli_has(r.out, d.out.substr(at, d.out.find('\n', at) - at))) << r.out;
    }
    EXPECT_TRUE(check_cli_has(r.out, "check     ok: 1 frame resolved, 0 warnings")) << r.out;
    EXPECT_TRUE(r.err.empty()) << r.err;
    EXPECT_EQ(check_cli_file_count(c.dir), files + 1);  // deform's out.su2 only
}

TEST(CheckCli, ErrorsAreExitCode2WithTheMessage) {
    const RectBoxFiles c = rect_box_files();
    const auto unknown = write_text(c.dir / "unknown.json", R"({"markers": {"wing": {"translate": [1, 0]}}})");
    const CommandResult u = run_cli("check " + quoted(c.mesh) + " -m " + quoted(unknown));
    EXPECT_EQ(u.exit_code, 2) << u.err;
    EXPECT_TRUE(check_cli_has(u.err, "names marker 'wing', which the mesh does not have; the mesh has: rectangle, farfield"))
        << u.err;
    const auto no_file = write_text(c.dir / "nofile.json", R"({"markers": {"rectangle": {"displacement_file": "d.csv"}}})");
    const CommandResult f = run_cli("check " + quoted(c.mesh) + " -m " + quoted(no_file));
    EXPECT_EQ(f.exit_code, 2) << f.err;
    EXPECT_TRUE(check_cli_has(f.err, "d.csv")) << f.err;
    const auto out_of_plane = write_text(c.dir / "z.json", R"({"markers": {"rectangle": {"translate": [0, 0, 1]}}})");
    EXPECT_EQ(run_cli("check " + quoted(c.mesh) + " -m " + quoted(out_of_plane)).exit_code, 2);
    EXPECT_EQ(run_cli("check " + quoted(c.mesh)).exit_code, 1);  // no motion: usage
}

TEST(CheckCli, FindsAConflictThatOnlyALaterFrameShows) {
    const auto dir = scratch_dir();
    const auto mesh = check_cli_square(dir);
    // Two plunges at different frequencies on markers sharing node 0: equal
    // (zero) at step 0, which is all resolve_boundary checks of a periodic
    // motion, different from step 1 on.
    const auto motion = write_text(dir / "plunges.json", R"({"markers": {
        "left": {"periodic": {"plunge": {"amplitude": [0, 0.1], "frequency": 1}}},
        "bottom": {"periodic": {"plunge": {"amplitude": [0, 0.1], "frequency": 2}}}},
      "time": {"time_step": 0.1, "steps": 5}})");
    const CommandResult r = run_cli("check " + quoted(mesh) + " -m " + quoted(motion));
    EXPECT_EQ(r.exit_code, 2) << r.out << r.err;
    EXPECT_TRUE(check_cli_has(r.err, "frame 1: moving markers disagree on the nodes they share")) << r.err;
    EXPECT_TRUE(check_cli_has(r.err, "markers 'left' and 'bottom' on 1 node (e.g. node 0")) << r.err;
    // The same frequencies agree in every frame.
    const auto agree = write_text(dir / "agree.json", R"({"markers": {
        "left": {"periodic": {"plunge": {"amplitude": [0, 0.1], "frequency": 2}}},
        "bottom": {"periodic": {"plunge": {"amplitude": [0, 0.1], "frequency": 2}}}},
      "time": {"time_step": 0.1, "steps": 5}})");
    const CommandResult ok = run_cli("check " + quoted(mesh) + " -m " + quoted(agree));
    EXPECT_EQ(ok.exit_code, 0) << ok.err;
    EXPECT_TRUE(check_cli_has(ok.out, "check     ok: 5 frames resolved, 0 warnings")) << ok.out;
}

TEST(CheckCli, WarningsGoToStandardErrorAndKeepExitCode0) {
    const RectBoxFiles c = rect_box_files();
    const auto huge = write_text(c.dir / "huge.json", R"({"markers": {"rectangle": {"translate": [60, 0]}}})");
    const CommandResult r = run_cli("check " + quoted(c.mesh) + " -m " + quoted(huge));
    EXPECT_EQ(r.exit_code, 0) << r.err;
    // Once, though resolve_boundary and the frame both find it.
    const std::string said = "more than the diagonal of the mesh's bounding box";
    EXPECT_TRUE(check_cli_has(r.err, said)) << r.err;
    EXPECT_EQ(r.err.find(said), r.err.rfind(said)) << r.err;
    EXPECT_TRUE(check_cli_has(r.out, "check     ok: 1 frame resolved, 1 warning")) << r.out;
    const CommandResult q = run_cli("check " + quoted(c.mesh) + " -m " + quoted(huge) + " -q");
    EXPECT_EQ(q.exit_code, 0);
    EXPECT_TRUE(q.out.empty()) << q.out;
}

TEST(CheckCli, CheckAcceptsExactlyWhatDeformAccepts) {
    // Issue #27: an axis [0, 0, 1e-300] (any non-zero length, MOTION.md)
    // passed check and failed deform ("the motion ... is not finite"); a
    // translation of 1.7e308 too. Both now run one resolution: the same exit
    // code, and the tiny axis turns as the unit one does.
    const RectBoxFiles c = rect_box_files();
    struct Case {
        const char* json;
        int code;
    };
    const Case cases[] = {
        {R"({"markers": {"rectangle": {"rotate": {"angle_deg": 10, "axis": [0, 0, 1e-300], "center": [0, 0]}}}})", 0},
        {R"({"markers": {"rectangle": {"rotate": {"angle_deg": 10, "axis": [0, 0, 1e300], "center": [0, 0]}}}})", 0},
        {R"({"markers": {"rectangle": {"translate": [1.7e308, 0]}}})", 2},
        {R"({"markers": {"rectangle": {"translate": [1e308, 1e308]}}})", 2},
        {R"({"markers": {"rectangle": {"rotate": {"angle_deg": 1e300, "center": [0, 0]}}}})", 2},
    };
    for (std::size_t k = 0; k < std::size(cases); ++k) {
        const auto motion = write_text(c.dir / ("m" + std::to_string(k) + ".json"), cases[k].json);
        const CommandResult check = run_cli("check " + quoted(c.mesh) + " -m " + quoted(motion) + " -q");
        const CommandResult deform = run_cli("deform " + quoted(c.mesh) + " -m " + quoted(motion) + " -o " +
                                             quoted(c.dir / ("out" + std::to_string(k) + ".su2")) + " -q");
        EXPECT_EQ(check.exit_code, cases[k].code) << cases[k].json << "\n" << check.err;
        EXPECT_EQ(deform.exit_code, cases[k].code) << cases[k].json << "\n" << deform.err;
        if (cases[k].code != 0) {
            EXPECT_TRUE(check_cli_has(check.err, "marker 'rectangle' cannot move node")) << check.err;
            EXPECT_EQ(check.err, deform.err);
        }
    }
    // The tiny axis gives the unit axis' result, bit for bit.
    const auto unit = write_text(c.dir / "unit.json",
                                 R"({"markers": {"rectangle": {"rotate": {"angle_deg": 10, "axis": [0, 0, 1], "center": [0, 0]}}}})");
    ASSERT_EQ(run_cli("deform " + quoted(c.mesh) + " -m " + quoted(unit) + " -o " + quoted(c.dir / "unit.su2") + " -q")
                  .exit_code,
              0);
    EXPECT_EQ(slurp(c.dir / "out0.su2"), slurp(c.dir / "unit.su2"));
}

TEST(CheckCli, ABoundaryMotionThatFoldsItsOwnFacesIsNamedBeforeAnyStep) {
    // Issue #27: brick_rotate_top.json under static_wins folds z_p's own
    // faces; deform reported inverted_on_boundary 0 and advised a finer
    // coarse level (42 cells still, 9.5 s). check and deform now say so.
    const auto hex = su2_meshes_dir() / "deformation_brick_hex_mesh_brick_hex_ffd.su2";
    const auto dir = scratch_dir();
    std::string json = slurp(source_dir() / "examples/motions/brick_rotate_top.json");
    const auto moving_wins = write_text(dir / "moving.json", json);
    json.replace(json.find("\"moving_wins\""), 13, "\"static_wins\"");
    const auto static_wins = write_text(dir / "static.json", json);
    CommandResult r = run_cli("check " + quoted(hex) + " -m " + quoted(static_wins));
    EXPECT_EQ(r.exit_code, 0) << r.err;
    EXPECT_TRUE(check_cli_has(r.err, "the boundary motion itself folds ")) << r.err;
    EXPECT_TRUE(check_cli_has(r.err, "of marker 'z_p''s 741 faces")) << r.err;
    r = run_cli("deform " + quoted(hex) + " -m " + quoted(static_wins) + " -o " + quoted(dir / "o.su2") + " --json");
    EXPECT_EQ(r.exit_code, 3) << r.err;
    EXPECT_TRUE(check_cli_has(nlohmann::json::parse(r.out).at("warnings").dump(), "folds")) << r.out;
    // Under moving_wins the rim turns too: nothing folds, no warning.
    r = run_cli("check " + quoted(hex) + " -m " + quoted(moving_wins));
    EXPECT_EQ(r.exit_code, 0) << r.err;
    EXPECT_FALSE(check_cli_has(r.err, "folds")) << r.err;
}
