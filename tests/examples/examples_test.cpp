// The numbered examples (examples/*.cpp) run as a new user runs them: each
// binary in a scratch folder, its exit code, its key lines and its files
// checked, where possible against the library's own results.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>
#include <numbers>
#include <sstream>
#include <string>
#include <vector>

#include "dgwarp/cases/rect_box.hpp"
#include "dgwarp/io/mesh_io.hpp"
#include "dgwarp/plan/plan_file.hpp"
#include "dgwarp/methods/method.hpp"
#include "dgwarp/motion/resolve_motion.hpp"
#include "dgwarp/quality/mesh_quality.hpp"
#include "support/test_paths.hpp"

using namespace dgwarp;
using namespace dgwarp::test;

namespace {


/// Runs example `name` with `args` in `dir`.
CommandResult run_example(const std::string& name, const std::filesystem::path& dir, const std::string& args = "") {
    const auto exe = std::filesystem::path(DGWARP_EXAMPLES_DIR) / name;
    return run_command("cd " + quoted(dir) + " && " + quoted(exe) + " " + args);
}

bool has_line(const std::string& out, const std::string& line) {
    std::istringstream in(out);
    for (std::string l; std::getline(in, l);)
        if (l == line) return true;
    return false;
}

std::vector<std::string> lines_starting_with(const std::string& out, const std::string& prefix) {
    std::vector<std::string> found;
    std::istringstream in(out);
    for (std::string l; std::getline(in, l);)
        if (l.rfind(prefix, 0) == 0) found.push_back(l);
    return found;
}

std::vector<std::string> words(const std::string& line) {
    std::istringstream in(line);
    std::vector<std::string> w;
    for (std::string s; in >> s;) w.push_back(s);
    return w;
}

/// read_vtu.py's JSON summary of a VTU file (fails the test when the file is not valid).
nlohmann::json vtu_summary(const std::filesystem::path& file) {
    const CommandResult py = run_command(std::string(DGWARP_PYTHON) + " " +
                                         quoted(source_dir() / "tests/tools/read_vtu.py") + " " + quoted(file));
    EXPECT_EQ(py.exit_code, 0) << py.err;
    return py.exit_code == 0 ? nlohmann::json::parse(py.out) : nlohmann::json::object();
}

const nlohmann::json* vtu_array(const nlohmann::json& summary, const std::string& name) {
    for (const auto& a : summary.at("arrays"))
        if (a.at("name") == name) return &a;
    return nullptr;
}

/// The rect-box with the rectangle turned by `degrees` about the origin by
/// DG-IDW with default options, computed here with the library.
std::vector<double> rect_box_turned(double degrees) {
    const Mesh mesh = make_rect_box();
    NodeMotion turn;
    turn.rotation = {0, 0, degrees * std::numbers::pi / 180};
    MotionSpec spec;
    spec.frames.resize(1);
    spec.frames[0].markers["rectangle"] = RigidMotion{turn};
    const ResolvedBoundary resolved = resolve_boundary(mesh, spec);
    std::vector<double> out(mesh.points.size());
    deform(prepare(Method::dg_idw, mesh.dim, mesh.points, resolved.boundary), mesh.points,
           resolve_frame(mesh, spec, resolved, 0).motion, out);
    return out;
}

/// The coordinate sums read_vtu.py prints must be those of `points` (2D).
void expect_coordinate_sums(const nlohmann::json& summary, const std::vector<double>& points) {
    double sx = 0, sy = 0;
    for (std::size_t i = 0; i + 1 < points.size(); i += 2) {
        sx += points[i];
        sy += points[i + 1];
    }
    const auto& sums = summary.at("coordinate_sums");
    EXPECT_NEAR(sums.at(0).get<double>(), sx, 1e-8);
    EXPECT_NEAR(sums.at(1).get<double>(), sy, 1e-8);
    EXPECT_EQ(sums.at(2).get<double>(), 0.0);
}

}  // namespace

TEST(Examples, ReadAndMeasurePrintsTheBuiltInMeshAndAFile) {
    const auto dir = scratch_dir();
    const Mesh mesh = make_rect_box();
    const std::string counts = "dim 2, points " + std::to_string(mesh.num_points()) + ", cells " +
                               std::to_string(mesh.cells.size());
    CommandResult r = run_example("01_read_and_measure", dir);
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_TRUE(has_line(r.out, counts)) << r.out;
    for (const Marker& m : mesh.markers)
        EXPECT_TRUE(has_line(r.out, "marker " + m.name + ": " + std::to_string(m.elements.size()) + " elements, " +
                                        std::to_string(marker_nodes(m).size()) + " nodes"))
            << r.out;
    EXPECT_TRUE(has_line(r.out, "inverted 0")) << r.out;

    // The same mesh through a file gives the same report.
    write_mesh(dir / "rect_box.su2", mesh);
    r = run_example("01_read_and_measure", dir, "rect_box.su2");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_TRUE(has_line(r.out, counts)) << r.out;
    EXPECT_TRUE(has_line(r.out, "inverted 0")) << r.out;

    // A missing file is an error that names it.
    r = run_example("01_read_and_measure", dir, "missing.su2");
    EXPECT_EQ(r.exit_code, 1);
    EXPECT_NE(r.err.find("missing.su2"), std::string::npos) << r.err;
}

TEST(Examples, DeformOnceWritesTheLibrarysResultAsAValidVtu) {
    const auto dir = scratch_dir();
    CommandResult r = run_example("02_deform_once", dir);
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_TRUE(has_line(r.out, "inverted 0")) << r.out;
    EXPECT_TRUE(has_line(r.out, "wrote deformed.vtu")) << r.out;

    const std::vector<double> expected = rect_box_turned(30);
    nlohmann::json vtu = vtu_summary(dir / "deformed.vtu");
    ASSERT_FALSE(vtu.empty());
    EXPECT_EQ(vtu.at("points"), 2340);
    EXPECT_EQ(vtu.at("cells"), 2262);
    expect_coordinate_sums(vtu, expected);
    const auto* displacement = vtu_array(vtu, "displacement");
    ASSERT_NE(displacement, nullptr);
    EXPECT_EQ(displacement->at("components"), 3);
    const auto* quality = vtu_array(vtu, "quality");
    ASSERT_NE(quality, nullptr);
    EXPECT_GT(quality->at("min").get<double>(), 0.0);
    EXPECT_LE(quality->at("max").get<double>(), 1.0 + 1e-12);
    EXPECT_NE(vtu_array(vtu, "quality_ratio"), nullptr);

    // The motion file form of the motion built in code gives the same mesh.
    write_mesh(dir / "rect_box.su2", make_rect_box());
    std::ofstream(dir / "turn.json") << R"({"markers": {"rectangle": {"rotate": {"angle_deg": 30, "center": [0, 0]}}}})";
    std::filesystem::remove(dir / "deformed.vtu");
    r = run_example("02_deform_once", dir, "rect_box.su2 turn.json");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    vtu = vtu_summary(dir / "deformed.vtu");
    ASSERT_FALSE(vtu.empty());
    expect_coordinate_sums(vtu, expected);

    // A marker the mesh does not have: an error listing the mesh's markers.
    std::ofstream(dir / "bad.json") << R"({"markers": {"wing": {"translate": [1, 0]}}})";
    r = run_example("02_deform_once", dir, "rect_box.su2 bad.json");
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_NE(r.err.find("rectangle"), std::string::npos) << r.err;
}

TEST(Examples, SolverTimeLoopRunsEveryStepAndWritesEveryKthFrame) {
    const auto dir = scratch_dir();
    CommandResult r = run_example("03_solver_time_loop", dir, "8 4");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_EQ(lines_starting_with(r.out, "step ").size(), 8u) << r.out;
    EXPECT_EQ(lines_starting_with(r.out, "steps 8,").size(), 1u) << r.out;
    EXPECT_TRUE(has_line(r.out, "inverted 0")) << r.out;
    for (const char* written : {"pitch_plunge_0000.vtu", "pitch_plunge_0004.vtu"}) {
        const nlohmann::json vtu = vtu_summary(dir / written);
        ASSERT_FALSE(vtu.empty()) << written;
        EXPECT_EQ(vtu.at("points"), 2340);
    }
    EXPECT_FALSE(std::filesystem::exists(dir / "pitch_plunge_0001.vtu"));

    // Without EVERY nothing is written; a bad argument is a usage error.
    const auto quiet = dir / "quiet";
    std::filesystem::create_directories(quiet);
    r = run_example("03_solver_time_loop", quiet, "3");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_TRUE(std::filesystem::is_empty(quiet));
    EXPECT_EQ(run_example("03_solver_time_loop", quiet, "zero").exit_code, 1);
}

TEST(Examples, SavedPlanIsReloadedAndDeformsBitIdentically) {
    const auto dir = scratch_dir();
    const CommandResult r = run_example("04_save_and_reuse_plan", dir);
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_TRUE(has_line(r.out, "bit-identical: yes")) << r.out;
    EXPECT_EQ(lines_starting_with(r.out, "other mesh: refused").size(), 1u) << r.out;
    const DgIdwPlan plan = load_dg_idw_plan(dir / "rect_box.plan");
    EXPECT_EQ(plan.num_points(), static_cast<std::int64_t>(make_rect_box().num_points()));
}

TEST(Examples, CompareMethodsListsEveryMethodAndReportsDgmsInvalidGraph) {
    const auto dir = scratch_dir();
    const CommandResult r = run_example("05_compare_methods", dir, "30 90");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    for (Method m : all_methods)
        for (const char* angle : {"30", "90"}) {
            const auto rows = lines_starting_with(r.out, std::string(method_name(m)) + " ");
            const auto row = std::find_if(rows.begin(), rows.end(),
                                          [&](const std::string& l) { return words(l).at(1) == angle; });
            EXPECT_NE(row, rows.end()) << method_name(m) << " " << angle << "\n" << r.out;
        }
    for (const std::string& row : lines_starting_with(r.out, "dg-idw ")) {
        const auto w = words(row);
        if (w.at(1) == "30") {
            EXPECT_EQ(w.at(6), "0") << row;  // inverted
            EXPECT_EQ(w.at(7), "ok") << row;
        }
    }
    for (const std::string& row : lines_starting_with(r.out, "dgm ")) {
        const auto w = words(row);
        if (w.at(1) == "30") {
            EXPECT_EQ(w.at(7), "ok") << row;
        } else if (w.at(1) == "90") {
            EXPECT_NE(row.find("invalid graph ("), std::string::npos) << row;
        }
    }
}

TEST(Examples, RunFramesWritesEveryValidFrameAsTheRunLayerMeasuredIt) {
    const auto dir = scratch_dir();
    CommandResult r = run_example("06_run_frames", dir);
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const auto frames = lines_starting_with(r.out, "frame ");
    ASSERT_EQ(frames.size(), 8u) << r.out;
    EXPECT_TRUE(has_line(r.out, "frames 8, valid: yes")) << r.out;
    const Mesh box = make_rect_box();
    for (int k = 0; k < 8; ++k) {
        char name[32];
        std::snprintf(name, sizeof name, "frame_%04d.vtu", k);
        const Mesh frame = read_mesh(dir / name);
        ASSERT_EQ(frame.points.size(), box.points.size()) << name;
        // The printed min quality is the written frame's own.
        const double printed = std::stod(words(frames[static_cast<std::size_t>(k)]).at(8));
        const double measured = summarize_quality(cell_qualities(frame, cell_orientations(box))).min;
        EXPECT_NEAR(printed, measured, 1e-4) << frames[static_cast<std::size_t>(k)];
    }
    // Frame 0 of the pitch (sin 0) does not move anything.
    EXPECT_EQ(read_mesh(dir / "frame_0000.vtu").points, box.points);

    // A motion that pushes the rectangle through the farfield: an invalid frame, exit 3, not written.
    write_mesh(dir / "rect_box.su2", box);
    std::ofstream(dir / "far.json") << R"({"markers": {"rectangle": {"translate": [0, 25]}}})";
    const auto quiet = dir / "far";
    std::filesystem::create_directories(quiet);
    r = run_example("06_run_frames", quiet, "../rect_box.su2 ../far.json dg-idw");
    EXPECT_EQ(r.exit_code, 3) << r.out << r.err;
    EXPECT_TRUE(has_line(r.out, "frames 1, valid: no")) << r.out;
    EXPECT_FALSE(std::filesystem::exists(quiet / "frame_0000.vtu"));
    // An unknown method: an error, exit 2.
    EXPECT_EQ(run_example("06_run_frames", quiet, "../rect_box.su2 ../far.json nomethod").exit_code, 2);
}

