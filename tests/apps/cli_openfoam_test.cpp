// `dgwarp deform` and `dgwarp convert` on OpenFOAM case folders, end to end:
// the moved points go where OpenFOAM reads them and nothing else changes;
// conversions between OpenFOAM and every other format are exact.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <nlohmann/json.hpp>

#include "dgwarp/io/mesh_io.hpp"
#include "dgwarp/io/openfoam/openfoam.hpp"
#include "dgwarp/mesh/planar_case.hpp"
#include "io/openfoam/openfoam_test_support.hpp"
#include "support/test_paths.hpp"

using namespace dgwarp;
using namespace dgwarp::test;

namespace {

const char* foam_lift_top = R"({"markers": {"top": {"translate": [0, 0, 0.05]}}})";

/// A copy of the committed case `name` in a scratch folder.
std::filesystem::path foam_case_copy(const std::string& name, const std::filesystem::path& dir) {
    std::filesystem::copy(openfoam_case(name), dir / name, std::filesystem::copy_options::recursive);
    return dir / name;
}

/// Every regular file under `dir` (relative path -> bytes).
std::map<std::string, std::string> foam_tree(const std::filesystem::path& dir) {
    std::map<std::string, std::string> files;
    for (const auto& e : std::filesystem::recursive_directory_iterator(dir))
        if (e.is_regular_file()) files[std::filesystem::relative(e.path(), dir).string()] = slurp(e.path());
    return files;
}

/// The mesh of case `dir` with the points of `points_file`.
Mesh foam_with_points(const std::filesystem::path& dir, const std::filesystem::path& points_file) {
    PolyMeshFiles files;
    const auto pm = find_poly_mesh(dir);
    files = {slurp(points_file), slurp(pm / "faces"), slurp(pm / "owner"), slurp(pm / "neighbour"), slurp(pm / "boundary")};
    return read_openfoam_files(pm, files);
}

}  // namespace

TEST(CliOpenFoam, DeformIntoTheInputCaseWritesOnlyATimeFolderPointsFile) {
    const auto dir = scratch_dir();
    const auto motion = write_text(dir / "lift.json", foam_lift_top);
    for (const std::string name : {"mixed", "mixed-binary"}) {
        const auto c = foam_case_copy(name, dir);
        const auto before = foam_tree(c);
        const CommandResult r = run_cli("deform " + quoted(c) + " -m " + quoted(motion) + " -o " + quoted(c));
        ASSERT_EQ(r.exit_code, 0) << r.err;
        EXPECT_NE(r.out.find("wrote " + (c / "0" / "polyMesh" / "points").string()), std::string::npos) << r.out;
        auto after = foam_tree(c);
        ASSERT_EQ(after.size(), before.size() + 1);
        const std::string points = after.at("0/polyMesh/points");
        after.erase("0/polyMesh/points");
        EXPECT_EQ(after, before) << name << ": a file of the case changed";
        // Points in the input's format, where OpenFOAM looks for them; the top moved by exactly 0.05.
        EXPECT_NE(points.find(name == "mixed" ? "format      ascii;" : "format      binary;"), std::string::npos);
        EXPECT_NE(points.find("location    \"0/polyMesh\";"), std::string::npos);
        const Mesh original = read_mesh(c);
        const Mesh moved = foam_with_points(c, c / "0" / "polyMesh" / "points");
        EXPECT_EQ(moved.cells, original.cells);
        for (NodeId n : marker_nodes(find_marker(original, "top")))
            EXPECT_EQ(moved.points[3 * n + 2], original.points[3 * n + 2] + 0.05) << n;
        for (NodeId n : marker_nodes(find_marker(original, "bottom")))
            for (int d = 0; d < 3; ++d) EXPECT_EQ(moved.points[3 * n + d], original.points[3 * n + d]) << n;
    }
}

TEST(CliOpenFoam, DeformIntoAnotherFolderCopiesThePolyMeshAndMatchesAnSu2Output) {
    const auto dir = scratch_dir();
    const auto motion = write_text(dir / "lift.json", foam_lift_top);
    const auto c = foam_case_copy("mixed", dir);
    const std::string base = "deform " + quoted(c) + " -m " + quoted(motion) + " -q -o ";
    const CommandResult r = run_cli(base + quoted(dir / "out/") + " --foam-time 0.25 --json");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const auto j = nlohmann::json::parse(r.out);
    EXPECT_EQ(j.at("output"), (dir / "out/").string());  // -o as given
    EXPECT_EQ(j.at("frames").at(0).at("output"), (dir / "out" / "0.25" / "polyMesh" / "points").string());
    ASSERT_EQ(run_cli(base + quoted(dir / "out.su2")).exit_code, 0);
    // out/constant/polyMesh: the input's files byte for byte (zones too); the points at 0.25.
    const auto copied = foam_tree(dir / "out" / "constant");
    EXPECT_EQ(copied, foam_tree(c / "constant"));
    EXPECT_TRUE(read_mesh(dir / "out") == read_mesh(c));
    const Mesh su2 = read_mesh(dir / "out.su2");
    EXPECT_EQ(foam_with_points(dir / "out", dir / "out" / "0.25" / "polyMesh" / "points").points, su2.points);
    // --foam-time constant: the moved points replace the copy's.
    ASSERT_EQ(run_cli(base + quoted(dir / "replaced") + " --foam-time constant").exit_code, 0);
    EXPECT_EQ(read_mesh(dir / "replaced").points, su2.points);
    EXPECT_FALSE(std::filesystem::exists(dir / "replaced" / "0"));
}

TEST(CliOpenFoam, DeformRefusesToOverwriteTheInputAndChecksTimeNames) {
    const auto dir = scratch_dir();
    const auto motion = write_text(dir / "lift.json", foam_lift_top);
    const auto c = foam_case_copy("cavity", dir);
    const auto before = foam_tree(c);
    const std::string base = "deform " + quoted(c) + " -m " + quoted(motion) + " -o ";
    CommandResult r = run_cli(base + quoted(c) + " --foam-time constant");
    EXPECT_EQ(r.exit_code, 1);
    EXPECT_NE(r.err.find("constant/polyMesh/points is an input of this command"), std::string::npos) << r.err;
    r = run_cli(base + quoted(c) + " --foam-time 1/2");
    EXPECT_EQ(r.exit_code, 1);
    EXPECT_NE(r.err.find("is not a time folder's name"), std::string::npos) << r.err;
    r = run_cli(base + quoted(dir / "out.su2") + " --foam-time 1");
    EXPECT_EQ(r.exit_code, 1);
    EXPECT_NE(r.err.find("is for an OpenFOAM case output"), std::string::npos) << r.err;
    EXPECT_EQ(foam_tree(c), before);
    // A 2D mesh cannot become an OpenFOAM case.
    ASSERT_EQ(run_cli("case naca0012 -q -o " + quoted(dir / "n.su2")).exit_code, 0);
    r = run_cli("deform " + quoted(dir / "n.su2") + " -m " + quoted(source_dir() / "examples/motions/airfoil_rotate.json") +
                " -o " + quoted(dir / "n2d/"));
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_NE(r.err.find("OpenFOAM meshes are 3D"), std::string::npos) << r.err;
    EXPECT_FALSE(std::filesystem::exists(dir / "n2d"));
}

TEST(CliOpenFoam, ASeriesWritesOneTimeFolderPerFrame) {
    const auto dir = scratch_dir();
    const auto periodic = write_text(dir / "periodic.json", R"({"markers": {"top": {"periodic": {
        "plunge": {"amplitude": [0, 0, 0.05], "frequency": 1.0, "phase_deg": 0}}}},
        "time": {"time_step": 0.1, "steps": 3}})");
    const auto frames = write_text(dir / "frames.json", R"({"frames": [
        {"markers": {"top": {"translate": [0, 0, 0.02]}}}, {"markers": {"top": {"translate": [0, 0, 0.04]}}}]})");
    const auto c = openfoam_case("mixed");
    ASSERT_EQ(run_cli("deform " + quoted(c) + " -q -m " + quoted(periodic) + " -o " + quoted(dir / "p")).exit_code, 0);
    for (const char* t : {"0", "0.1", "0.2"}) EXPECT_TRUE(std::filesystem::exists(dir / "p" / t / "polyMesh" / "points")) << t;
    ASSERT_EQ(run_cli("deform " + quoted(c) + " -q -m " + quoted(frames) + " -o " + quoted(dir / "f")).exit_code, 0);
    for (const char* t : {"0", "1"}) EXPECT_TRUE(std::filesystem::exists(dir / "f" / t / "polyMesh" / "points")) << t;
    const Mesh second = foam_with_points(dir / "f", dir / "f" / "1" / "polyMesh" / "points");
    const Mesh original = read_mesh(c);
    const NodeId n = marker_nodes(find_marker(original, "top")).front();
    EXPECT_EQ(second.points[3 * n + 2], original.points[3 * n + 2] + 0.04);
    const CommandResult r =
        run_cli("deform " + quoted(c) + " -q -m " + quoted(frames) + " -o " + quoted(dir / "g") + " --foam-time 3");
    EXPECT_EQ(r.exit_code, 1);
    EXPECT_NE(r.err.find("this motion has 2 frames"), std::string::npos) << r.err;
}

// A decomposed case: each processor gets its own points, in its numbering and
// format; the processors' files are otherwise untouched (or copied).
TEST(CliOpenFoam, DeformADecomposedCaseWritesEachProcessorsPoints) {
    const auto dir = scratch_dir();
    const auto motion = write_text(dir / "lift.json", foam_lift_top);
    ASSERT_EQ(run_cli("deform " + quoted(openfoam_case("mixed")) + " -q -m " + quoted(motion) + " -o " +
                      quoted(dir / "whole.su2"))
                  .exit_code,
              0);
    const Mesh moved = read_mesh(dir / "whole.su2");
    const auto c = foam_case_copy("mixed-decomposed", dir);
    const auto before = foam_tree(c);
    CommandResult r = run_cli("deform " + quoted(c) + " -m " + quoted(motion) + " -o " + quoted(c));
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(r.out.find("wrote " + (c / "processor*" / "0" / "polyMesh" / "points").string()), std::string::npos) << r.out;
    auto after = foam_tree(c);
    OpenFoamSource source;
    read_openfoam(c, {}, &source);
    ASSERT_EQ(source.processors.size(), 2u);
    for (std::size_t p = 0; p < 2; ++p) {
        const std::string file = "processor" + std::to_string(p) + "/0/polyMesh/points";
        ASSERT_EQ(after.count(file), 1u) << file;
        EXPECT_EQ(after.at(file),
                  openfoam_points_text(processor_points(source.processors[p], moved.points), foam::Format::ascii, "0/polyMesh"));
        after.erase(file);
    }
    EXPECT_EQ(after, before);
    // Into another folder: each processor's polyMesh copied, then its points.
    r = run_cli("deform " + quoted(c) + " -q -m " + quoted(motion) + " -o " + quoted(dir / "out/") + " --foam-time constant");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_EQ(read_mesh(dir / "out").points, moved.points);
    EXPECT_EQ(slurp(dir / "out/processor1/constant/polyMesh/faceProcAddressing"),
              slurp(c / "processor1/constant/polyMesh/faceProcAddressing"));
    // The input's points are not an output.
    r = run_cli("deform " + quoted(c) + " -q -m " + quoted(motion) + " -o " + quoted(c) + " --foam-time constant");
    EXPECT_EQ(r.exit_code, 1);
    EXPECT_NE(r.err.find("processor0/constant/polyMesh/points is an input of this command"), std::string::npos) << r.err;
}

// A damaged case: exit 2, the file and line named, nothing written.
TEST(CliOpenFoam, ADamagedCaseIsReportedAndNothingIsWritten) {
    const auto dir = scratch_dir();
    const auto motion = write_text(dir / "lift.json", foam_lift_top);
    const auto c = foam_case_copy("mixed", dir);
    const auto faces = c / "constant" / "polyMesh" / "faces";
    const std::string text = slurp(faces);
    write_text(faces, text.substr(0, text.size() / 2));
    const auto before = foam_tree(c);
    for (const std::string& args : {"convert " + quoted(c) + " " + quoted(dir / "out.su2"),
                                    "convert " + quoted(c) + " " + quoted(dir / "out/"),
                                    "deform " + quoted(c) + " -m " + quoted(motion) + " -o " + quoted(c)}) {
        const CommandResult r = run_cli(args);
        EXPECT_EQ(r.exit_code, 2) << args;
        // The faces' count on line 19 is more than half a file can hold.
        EXPECT_NE(r.err.find(faces.string() + ":19: expected a size of faces that the rest of the file can hold"),
                  std::string::npos)
            << r.err;
    }
    EXPECT_FALSE(std::filesystem::exists(dir / "out.su2"));
    EXPECT_FALSE(std::filesystem::exists(dir / "out"));
    EXPECT_EQ(foam_tree(c), before);
}

TEST(CliOpenFoam, ConvertRoundTripsThroughEveryFormatExactly) {
    const auto dir = scratch_dir();
    for (const std::string name : {"mixed", "cavity-binary"}) {
        const auto c = openfoam_case(name);
        const Mesh original = read_mesh(c);
        for (const char* ext : {".su2", ".msh", ".vtu"}) {
            const auto file = dir / (name + ext), back = dir / (name + "-from-" + std::string(ext + 1));
            ASSERT_EQ(run_cli("convert -q " + quoted(c) + " " + quoted(file)).exit_code, 0) << ext;
            EXPECT_TRUE(read_mesh(file) == original) << name << ext;
            ASSERT_EQ(run_cli("convert -q " + quoted(file) + " " + quoted(back)).exit_code, 0) << ext;
            EXPECT_TRUE(read_mesh(back) == original) << name << ext << " back to OpenFOAM";
        }
        // OpenFOAM to OpenFOAM keeps the patch types and the format (or takes --foam-format).
        const auto copy = dir / (name + "-copy");
        ASSERT_EQ(run_cli("convert -q " + quoted(c) + " " + quoted(copy)).exit_code, 0);
        EXPECT_TRUE(read_mesh(copy) == original);
        EXPECT_EQ(slurp(copy / "constant/polyMesh/points").find("binary") != std::string::npos, name == "cavity-binary");
        const std::string boundary = slurp(copy / "constant/polyMesh/boundary");
        EXPECT_NE(boundary.find(name == "mixed" ? "physicalType patch;" : "type            empty;"), std::string::npos);
        ASSERT_EQ(run_cli("convert -q --foam-format ascii " + quoted(c) + " " + quoted(dir / (name + "-ascii/"))).exit_code, 0);
        EXPECT_EQ(slurp(dir / (name + "-ascii") / "constant/polyMesh/points").find("binary"), std::string::npos);
        EXPECT_TRUE(read_mesh(dir / (name + "-ascii")) == original);
    }
    // The input case is not an output.
    const auto c = foam_case_copy("cavity", dir);
    const auto before = foam_tree(c);
    const CommandResult r = run_cli("convert " + quoted(c) + " " + quoted(c));
    EXPECT_EQ(r.exit_code, 1);
    EXPECT_NE(r.err.find("is an input of this command"), std::string::npos) << r.err;
    EXPECT_EQ(foam_tree(c), before);
}

TEST(CliOpenFoam, Su2MeshesConvertToOpenFoamAndBackInTheDocumentedOrder) {
    DGWARP_REQUIRE_SHARED_MESHES();
    const auto dir = scratch_dir();
    const auto su2 = su2_meshes_dir() / "deformation_brick_prism_mesh_brick_prism_ffd.su2";
    ASSERT_EQ(run_cli("convert -q " + quoted(su2) + " " + quoted(dir / "brick/")).exit_code, 0);
    ASSERT_EQ(run_cli("convert -q " + quoted(dir / "brick") + " " + quoted(dir / "brick.su2")).exit_code, 0);
    ASSERT_EQ(run_cli("convert -q " + quoted(dir / "brick.su2") + " " + quoted(dir / "again")).exit_code, 0);
    const Mesh original = read_mesh(su2), once = read_mesh(dir / "brick");
    EXPECT_EQ(once.points, original.points);
    EXPECT_EQ(once.cells.types, original.cells.types);
    EXPECT_EQ(once.markers.size(), original.markers.size());
    EXPECT_TRUE(read_mesh(dir / "brick.su2") == once);
    EXPECT_TRUE(read_mesh(dir / "again") == once);
    const CommandResult info = run_cli("info " + quoted(dir / "brick"));
    EXPECT_EQ(info.exit_code, 0) << info.err;
    EXPECT_NE(info.out.find("inverted      0 of " + std::to_string(original.cells.size())), std::string::npos) << info.out;
}

// decomposePar's usual layout (constant/polyMesh and processor folders): the
// whole mesh is read and written, and a warning names the processor folders
// a parallel run would read, which stay as they were (issue #30 item 4).
TEST(CliOpenFoam, AnUsualDecomposedLayoutSaysOnlyTheWholeMeshIsDeformed) {
    const auto dir = scratch_dir();
    const auto motion = write_text(dir / "lift.json", foam_lift_top);
    const auto c = foam_case_copy("mixed", dir);
    for (const char* p : {"processor0", "processor1"})
        std::filesystem::copy(openfoam_case("mixed-decomposed") / p, c / p, std::filesystem::copy_options::recursive);
    const auto processors_before = foam_tree(c / "processor1");
    CommandResult r = run_cli("deform " + quoted(c) + " -m " + quoted(motion) + " -o " + quoted(c));
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const std::string expected = c.string() +
                                 " holds constant/polyMesh and 2 processor folders (processor0 ... processor1): this run "
                                 "reads and writes the whole mesh (constant/polyMesh) only";
    EXPECT_NE(r.err.find("warning: " + expected), std::string::npos) << r.err;
    EXPECT_TRUE(std::filesystem::exists(c / "0" / "polyMesh" / "points"));
    EXPECT_FALSE(std::filesystem::exists(c / "processor0" / "0"));
    EXPECT_EQ(foam_tree(c / "processor1"), processors_before);
    r = run_cli("deform " + quoted(c) + " -m " + quoted(motion) + " -o " + quoted(dir / "out.su2") + " --json");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const auto j = nlohmann::json::parse(r.out);
    bool found = false;
    for (const auto& w : j.at("warnings")) found = found || w.get<std::string>().starts_with(expected);
    EXPECT_TRUE(found) << j.at("warnings").dump();
    bool coded = false;
    for (const auto& w : j.at("warning_items"))
        coded = coded || (w.at("code") == "processors-unchanged" && w.at("count") == 2);
    EXPECT_TRUE(coded) << j.at("warning_items").dump();
    // Without constant/polyMesh the same folder is the decomposed case: no warning.
    std::filesystem::remove_all(c / "constant" / "polyMesh");
    std::filesystem::remove_all(c / "0");
    r = run_cli("deform " + quoted(c) + " -m " + quoted(motion) + " -o " + quoted(c));
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_EQ(r.err.find("processor folders"), std::string::npos) << r.err;
}

/// Case `dir` (its files maybe gzipped) with the points of `points_file`, read from a copy in `copy`.
Mesh foam_case_with_points(const std::filesystem::path& dir, const std::filesystem::path& points_file,
                           const std::filesystem::path& copy) {
    std::filesystem::copy(dir, copy, std::filesystem::copy_options::recursive);
    std::filesystem::remove(copy / "constant/polyMesh/points.gz");
    std::filesystem::copy_file(points_file, copy / "constant/polyMesh/points",
                               std::filesystem::copy_options::overwrite_existing);
    return read_mesh(copy);
}

// 2D and axisymmetric cases (issue #30 item 2): the empty and wedge patches
// slide by their type, and the case is deformed as its 2D mesh. The result is
// valid, every point stays in its plane (the empty planes exactly), and twins
// across the layer stay twins.
TEST(CliOpenFoam, TwoDAndAxisymmetricCasesDeformInTheirPlanes) {
    const auto dir = scratch_dir();
    // pitzDaily (coarse) with its lower wall raised 1 mm, its ends held by the inlet and outlet.
    const auto raise = write_text(dir / "raise.json",
                                  R"({"shared_nodes": "static_wins", "markers": {"lowerWall": {"translate": [0, 0.001, 0]}}})");
    const auto pitz = foam_case_copy("pitz-daily-coarse", dir);
    CommandResult r = run_cli("deform " + quoted(pitz) + " -m " + quoted(raise) + " -o " + quoted(dir / "pitz-out/") + " --json");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    nlohmann::json report = nlohmann::json::parse(r.out);
    EXPECT_EQ(report["boundary"]["sliding_by_type"], nlohmann::json::array({"frontAndBack"}));
    ASSERT_TRUE(report["boundary"]["planar"].is_object());
    EXPECT_EQ(report["boundary"]["planar"]["nodes"], 1146);
    EXPECT_EQ(report["frames"][0]["quality"]["inverted"], 0);
    EXPECT_EQ(report["mesh"]["dim"], 3);
    const Mesh before = read_mesh(pitz);
    const Mesh after = foam_case_with_points(pitz, dir / "pitz-out/0/polyMesh/points", dir / "pitz-moved");
    const std::size_t empty_planes[] = {4};  // frontAndBack
    const PlanarCase planar = *find_planar_case(before, empty_planes).planar;
    std::size_t changed = 0;
    for (std::size_t v = 0; v < before.num_points(); ++v) {
        EXPECT_EQ(after.points[3 * v + 2], before.points[3 * v + 2]) << v;  // z exactly
        // A node moves as its twin on the first plane (blockMesh's twins differ by round-off: so may their moves).
        const auto twin = static_cast<std::size_t>(planar.node_3d[static_cast<std::size_t>(planar.node_2d[v])]);
        for (std::size_t k = 0; k < 2; ++k)
            EXPECT_NEAR(after.points[3 * v + k] - before.points[3 * v + k],
                        after.points[3 * twin + k] - before.points[3 * twin + k], 1e-17) << v;
        changed += after.points[3 * v] != before.points[3 * v] || after.points[3 * v + 1] != before.points[3 * v + 1];
    }
    EXPECT_GT(changed, 200u);  // the volume moved with the wall, not only the wall

    // movingCone with its cone moved 1 mm along the axis, its far fields slipping.
    const auto push = write_text(dir / "push.json",
                                 R"({"markers": {"movingWall": {"translate": [0.001, 0, 0]}, "farFieldMoving": "slide", "farField": "slide"}})");
    const auto cone = foam_case_copy("moving-cone", dir);
    r = run_cli("deform " + quoted(cone) + " -m " + quoted(push) + " -o " + quoted(dir / "cone-out/") + " --json");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    report = nlohmann::json::parse(r.out);
    EXPECT_EQ(report["boundary"]["sliding_by_type"], nlohmann::json::array({"back", "front"}));
    EXPECT_EQ(report["frames"][0]["quality"]["inverted"], 0);
    const Mesh cone_before = read_mesh(cone);
    const Mesh cone_after = foam_case_with_points(cone, dir / "cone-out/0/polyMesh/points", dir / "cone-moved");
    const std::size_t wedge_planes[] = {6, 7};  // back, front
    const PlanarCase wedge = *find_planar_case(cone_before, wedge_planes).planar;
    for (std::size_t v = 0; v < cone_before.num_points(); ++v) {
        // In its plane: as far from it as it was (blockMesh's points are in it to round-off), to round-off.
        const auto& n = wedge.side[v] == 2 ? wedge.normal_second : wedge.normal;
        const auto distance = [&](const Mesh& m) {
            double d = 0;
            for (std::size_t k = 0; k < 3; ++k) d += n[k] * (m.points[3 * v + k] - wedge.origin[k]);
            return d;
        };
        EXPECT_NEAR(distance(cone_after), distance(cone_before), 1e-17) << v;
    }
    // The cone's nodes moved by 1 mm, the axis's stayed on it.
    for (NodeId v : marker_nodes(find_marker(cone_before, "movingWall")))
        EXPECT_NEAR(cone_after.points[3 * v] - cone_before.points[3 * v], 0.001, 1e-15);
    for (std::size_t v = 0; v < cone_before.num_points(); ++v)
        if (cone_before.points[3 * v + 1] == 0 && cone_before.points[3 * v + 2] == 0) {
            EXPECT_NEAR(std::hypot(cone_after.points[3 * v + 1], cone_after.points[3 * v + 2]), 0, 1e-18) << v;
        }
}

// An OpenFOAM case's zones (issue #30 item 5): a whole polyMesh written from
// it keeps the cell and point zones byte for byte (the same cells and points)
// and says it drops the face zones; another format says it drops them all.
TEST(CliOpenFoam, ConvertKeepsCellAndPointZonesAndNamesTheZonesItDrops) {
    const auto dir = scratch_dir();
    const auto source = openfoam_case("mixed") / "constant/polyMesh";
    CommandResult r = run_cli("convert " + quoted(openfoam_case("mixed")) + " " + quoted(dir / "case/"));
    ASSERT_EQ(r.exit_code, 0) << r.err;
    for (const char* zone : {"cellZones", "pointZones"})
        EXPECT_EQ(slurp(dir / "case/constant/polyMesh" / zone), slurp(source / zone)) << zone;
    EXPECT_FALSE(std::filesystem::exists(dir / "case/constant/polyMesh/faceZones"));
    EXPECT_NE(r.err.find("does not keep " + openfoam_case("mixed").string() + "'s faceZones (OpenFOAM zones"),
              std::string::npos) << r.err;
    r = run_cli("convert " + quoted(openfoam_case("mixed")) + " " + quoted(dir / "mixed.su2"));
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(r.err.find("'s cellZones, faceZones, pointZones (OpenFOAM zones; an OpenFOAM case output keeps"),
              std::string::npos) << r.err;
    // A case without zones says nothing.
    r = run_cli("convert " + quoted(openfoam_case("cavity")) + " " + quoted(dir / "cavity.su2"));
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_EQ(r.err.find("zones"), std::string::npos) << r.err;
}

// CGNS BC names OpenFOAM cannot hold (cgns-convert's "UserDefined 1", issue
// #30 item 5): convert and deform write them with '_' and say so (the motion
// naming them as the file does); --rename-marker names them.
TEST(CliOpenFoam, CgnsNamesWithBlanksBecomePatchNames) {
    const auto dir = scratch_dir();
    const auto cgns = source_dir() / "tests/data/cgns/mixed.cgns";
    CommandResult r = run_cli("convert " + quoted(cgns) + " " + quoted(dir / "case/") + " --rename-marker 'UserDefined 5=top'");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(r.err.find("cannot hold the marker name 'UserDefined 1': it is written as 'UserDefined_1'"), std::string::npos) << r.err;
    const Mesh mesh = read_mesh(dir / "case");
    std::vector<std::string> names;
    for (const Marker& m : mesh.markers) names.push_back(m.name);
    EXPECT_EQ(names, (std::vector<std::string>{"UserDefined_1", "UserDefined_2", "UserDefined_3", "UserDefined_4", "top"}));
    r = run_cli("convert " + quoted(cgns) + " " + quoted(dir / "x.su2") + " --rename-marker 'nosuch=top'");
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_NE(r.err.find("--rename-marker 'nosuch=top': unknown marker 'nosuch'; the mesh has: UserDefined 1"), std::string::npos) << r.err;
    const auto motion = write_text(dir / "lift.json", R"({"markers": {"top": {"translate": [0, 0, 0.01]}}})");
    r = run_cli("deform " + quoted(cgns) + " -m " + quoted(motion) + " -o " + quoted(dir / "moved/") + " --rename-marker 'UserDefined 5=top'");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(r.err.find("cannot hold the marker name 'UserDefined 2': it is written as 'UserDefined_2'"), std::string::npos) << r.err;
    const Mesh moved = read_mesh(dir / "moved" / "0");
    ASSERT_EQ(moved.markers.size(), 5u);
    EXPECT_EQ(moved.markers[1].name, "UserDefined_2");
    // The motion names a marker as the file does: it moves the renamed patch.
    const auto by_file_name =
        write_text(dir / "lift2.json", R"({"markers": {"UserDefined 5": {"translate": [0, 0, 0.01]}}})");
    r = run_cli("deform " + quoted(cgns) + " -m " + quoted(by_file_name) + " -o " + quoted(dir / "moved2/") + " --json");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_EQ(nlohmann::json::parse(r.out)["boundary"]["moving_markers"], (nlohmann::json{"UserDefined_5"}));
    EXPECT_TRUE(read_mesh(dir / "moved2" / "0").points == moved.points);
}

// A time of a decomposed case as input: CASE/T, where the processors hold
// processorN/T/polyMesh/points (what deform writes), is the case's mesh with
// those points; deformed again, it may not overwrite its own points.
TEST(CliOpenFoam, ATimeOfADecomposedCaseReadsAsItsMeshWithThosePoints) {
    const auto dir = scratch_dir();
    const auto c = foam_case_copy("channel-cyclic-decomposed-4", dir);
    const auto motion =
        write_text(dir / "m.json", R"({"markers": {"bottomWall": {"translate": [0.3, 0.01, 0.2]}}})");
    ASSERT_EQ(run_cli("deform -q " + quoted(c) + " -m " + quoted(motion) + " -o " + quoted(dir / "serial/")).exit_code, 0);
    ASSERT_EQ(run_cli("deform -q " + quoted(c) + " -m " + quoted(motion) + " -o " + quoted(c) + " --foam-time 1").exit_code, 0);
    EXPECT_FALSE(std::filesystem::exists(c / "1"));  // decomposed times are the processors'
    const Mesh at_one = read_mesh(c / "1");
    EXPECT_TRUE(at_one.points == read_mesh(dir / "serial" / "0").points) << "not the deformed points";
    EXPECT_TRUE(at_one.cells == read_mesh(c).cells);
    CommandResult r = run_cli("quality " + quoted(c / "1"));
    EXPECT_EQ(r.exit_code, 0) << r.err;
    r = run_cli("deform " + quoted(c / "1") + " -m " + quoted(motion) + " -o " + quoted(c) + " --foam-time 1");
    EXPECT_EQ(r.exit_code, 1) << r.err;
    EXPECT_NE(r.err.find("polyMesh/points is an input of this command"), std::string::npos) << r.err;
    // From time 1 to time 2: the motion applied to the time-1 mesh.
    ASSERT_EQ(run_cli("deform -q " + quoted(c / "1") + " -m " + quoted(motion) + " -o " + quoted(c) + " --foam-time 2").exit_code, 0);
    const Mesh at_two = read_mesh(c / "2");
    EXPECT_FALSE(at_two.points == at_one.points);
    // A time no processor has: no such file.
    r = run_cli("quality " + quoted(c / "7"));
    EXPECT_EQ(r.exit_code, 2) << r.err;
    EXPECT_NE(r.err.find("No such file or directory"), std::string::npos) << r.err;
}

// A time folder as input (issue #30 item 5): CASE/T holding polyMesh/points
// (what deform writes) is the case's mesh with those points.
TEST(CliOpenFoam, ATimeFolderReadsAsTheMeshWithItsPoints) {
    const auto dir = scratch_dir();
    const auto c = foam_case_copy("mixed", dir);
    const auto motion = write_text(dir / "lift.json", foam_lift_top);
    ASSERT_EQ(run_cli("deform -q " + quoted(c) + " -m " + quoted(motion) + " -o " + quoted(c) + " --foam-time 0.5").exit_code, 0);
    const Mesh original = read_mesh(c);
    for (const std::string time : {"0.5", "0.5/"}) {
        const Mesh moved = read_mesh(c / time);
        EXPECT_EQ(moved.cells, original.cells);
        EXPECT_EQ(moved.markers, original.markers);
        EXPECT_TRUE(moved.points == foam_with_points(c, c / "0.5/polyMesh/points").points) << time;
        EXPECT_NE(moved.points, original.points);
    }
    const CommandResult q = run_cli("quality " + quoted(c / "0.5") + " --json");
    ASSERT_EQ(q.exit_code, 0) << q.err;
    // Deforming the time folder's mesh into its own time folder would overwrite what it reads.
    const CommandResult again = run_cli("deform " + quoted(c / "0.5") + " -m " + quoted(motion) + " -o " + quoted(c) + " --foam-time 0.5");
    EXPECT_EQ(again.exit_code, 1) << again.err;
    EXPECT_NE(again.err.find("0.5/polyMesh/points"), std::string::npos) << again.err;
}

// decomposePar's usual layout (constant/polyMesh and processor folders) with
// --foam-processors (issue #30 item 4): the whole mesh and every processor
// folder are written, the processors' points the same bytes as deforming the
// processor folders alone.
TEST(CliOpenFoam, FoamProcessorsWritesTheProcessorFoldersBesideTheWholeCase) {
    const auto dir = scratch_dir();
    const auto motion = write_text(dir / "lift.json", foam_lift_top);
    const auto both = dir / "both";
    std::filesystem::copy(openfoam_case("mixed"), both, std::filesystem::copy_options::recursive);
    for (const char* p : {"processor0", "processor1"})
        std::filesystem::copy(openfoam_case("mixed-decomposed") / p, both / p, std::filesystem::copy_options::recursive);
    const auto parts = foam_case_copy("mixed-decomposed", dir);
    ASSERT_EQ(run_cli("deform -q " + quoted(parts) + " -m " + quoted(motion) + " -o " + quoted(parts)).exit_code, 0);
    const CommandResult r = run_cli("deform " + quoted(both) + " -m " + quoted(motion) + " -o " + quoted(both) + " --foam-processors");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_EQ(r.err.find("does not change"), std::string::npos) << r.err;  // no warning about the processor folders
    EXPECT_TRUE(std::filesystem::exists(both / "0/polyMesh/points"));
    for (const char* p : {"processor0", "processor1"})
        EXPECT_EQ(slurp(both / p / "0/polyMesh/points"), slurp(parts / p / "0/polyMesh/points")) << p;
    // Into another folder: the processors' polyMesh folders are copied there too.
    ASSERT_EQ(run_cli("deform -q " + quoted(both) + " -m " + quoted(motion) + " -o " + quoted(dir / "out") + " --foam-processors").exit_code, 0);
    EXPECT_EQ(slurp(dir / "out/processor1/0/polyMesh/points"), slurp(parts / "processor1/0/polyMesh/points"));
    EXPECT_EQ(slurp(dir / "out/processor1/constant/polyMesh/pointProcAddressing"),
              slurp(both / "processor1/constant/polyMesh/pointProcAddressing"));
    // Without processor folders beside constant/polyMesh, the flag is a usage error.
    const CommandResult alone = run_cli("deform " + quoted(openfoam_case("mixed")) + " -m " + quoted(motion) + " -o " +
                                        quoted(dir / "x") + " --foam-processors");
    EXPECT_EQ(alone.exit_code, 1);
    EXPECT_NE(alone.err.find("--foam-processors"), std::string::npos) << alone.err;
}

TEST(CliOpenFoam, ASnappyHexMeshCaseWithPolyhedraDeformsWithEveryMethod) {
    // The sphere of the snappy case moved by 0.05 (its radius is 0.5, the
    // cells about it 0.125): no method inverts a cell, the sphere's
    // points move by exactly the motion, the box's stay; SU2 cannot hold the
    // polyhedra and says so, naming the first.
    const auto dir = scratch_dir();
    const auto c = foam_case_copy("snappy-sphere", dir);
    const auto motion = write_text(dir / "m.json", R"({"markers": {"sphere": {"translate": [0.05, 0, 0]}}})");
    const Mesh original = read_mesh(c);
    for (const std::string method : {"dg-harmonic", "dg-idw", "dgm", "idw", "rbf", "laplacian"}) {
        SCOPED_TRACE(method);
        const auto out = dir / ("out-" + method);
        const CommandResult r = run_cli("deform " + quoted(c) + " -m " + quoted(motion) + " --method " + method +
                                        " --json -o " + quoted(out / ""));
        ASSERT_EQ(r.exit_code, 0) << r.err;
        const nlohmann::json report = nlohmann::json::parse(r.out);
        // (48 snapped hexahedra have a concave corner as snappyHexMesh makes them: inverted by Knupp's measure.)
        EXPECT_EQ(report.at("frames").at(0).at("inverted_by_motion"), 0) << r.out;
        const Mesh moved = read_mesh(out / "0");
        EXPECT_EQ(moved.cells, original.cells);
        for (NodeId n : marker_nodes(find_marker(original, "sphere")))
            EXPECT_EQ(moved.points[3 * n], original.points[3 * n] + 0.05) << n;
        for (NodeId n : marker_nodes(find_marker(original, "sides")))
            for (int d = 0; d < 3; ++d) EXPECT_EQ(moved.points[3 * n + d], original.points[3 * n + d]) << n;
    }
    const CommandResult su2 = run_cli("convert " + quoted(c) + " " + quoted(dir / "s.su2"));
    EXPECT_EQ(su2.exit_code, 2);
    EXPECT_NE(su2.err.find("is a polyhedron, which SU2 files cannot hold (write .vtu, .cgns or an OpenFOAM case)"),
              std::string::npos)
        << su2.err;
    EXPECT_FALSE(std::filesystem::exists(dir / "s.su2"));
}

TEST(CliOpenFoam, CyclicPatchesMoveAsTheirImagesSeriallyAndDecomposed) {
    // channel395 coarsened (tests/data/openfoam/channel-cyclic): periodic in x
    // (inout, a translation by 4) and z (sides, by 2). Its bottom wall moved
    // along all three axes: fixed cyclic halves would shear the cells beside
    // them; coupled, every node of a half moves exactly as its image.
    const auto dir = scratch_dir();
    const auto motion =
        write_text(dir / "m.json", R"({"markers": {"bottomWall": {"translate": [0.3, 0.01, 0.2]}}})");
    CommandResult r = run_cli("deform " + quoted(openfoam_case("channel-cyclic")) + " -m " + quoted(motion) + " -o " +
                              quoted(dir / "serial/") + " --json");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const auto report = nlohmann::json::parse(r.out);
    EXPECT_EQ(report["boundary"]["cyclic_markers"].size(), 8u);
    EXPECT_EQ(report["boundary"]["cyclic_by_type"][0], (nlohmann::json{"sides1_half0", "sides1_half1"}));
    EXPECT_EQ(report["frames"][0]["quality"]["inverted"], 0);
    const Mesh before = read_mesh(openfoam_case("channel-cyclic"));
    const Mesh after = read_mesh(dir / "serial" / "0");
    ASSERT_EQ(after.num_points(), before.num_points());
    // Each node on x = 0 or z = 0 with its image 4 along x or 2 along z.
    std::size_t pairs = 0;
    double largest = 0;
    for (std::size_t a = 0; a < before.num_points(); ++a)
        for (std::size_t b = 0; b < before.num_points(); ++b) {
            const double* xa = &before.points[3 * a];
            const double* xb = &before.points[3 * b];
            const bool image = (std::abs(xb[0] - xa[0] - 4) < 1e-9 && std::abs(xb[1] - xa[1]) < 1e-9 && std::abs(xb[2] - xa[2]) < 1e-9) ||
                               (std::abs(xb[2] - xa[2] - 2) < 1e-9 && std::abs(xb[0] - xa[0]) < 1e-9 && std::abs(xb[1] - xa[1]) < 1e-9);
            if (!image) continue;
            ++pairs;
            for (std::size_t d = 0; d < 3; ++d) {
                const double da = after.points[3 * a + d] - xa[d], db = after.points[3 * b + d] - xb[d];
                EXPECT_NEAR(da, db, 1e-14) << a << " and " << b;
                largest = std::max(largest, std::abs(da));
            }
        }
    EXPECT_EQ(pairs, 11u * 7 + 9u * 11);  // inout: 11 x 7 nodes (y by z); sides: 9 x 11 (x by y)
    EXPECT_GT(largest, 0.05);
    // The same case decomposePar'd in 2 (simple) and 4 (hierarchical), its
    // processorCyclic faces read back into their cyclic patches: each
    // processor's points are the serial case's.
    const std::vector<double> serial = foam_body_numbers(slurp(dir / "serial" / "0" / "polyMesh" / "points"));
    for (const std::string name : {"channel-cyclic-decomposed", "channel-cyclic-decomposed-4"}) {
        SCOPED_TRACE(name);
        const auto c = foam_case_copy(name, dir);
        r = run_cli("deform " + quoted(c) + " -m " + quoted(motion) + " -o " + quoted(c) + " --foam-time 1");
        ASSERT_EQ(r.exit_code, 0) << r.err;
        OpenFoamSource source;
        read_openfoam(c, {}, &source);
        for (const OpenFoamProcessor& p : source.processors) {
            const std::vector<double> ours =
                foam_body_numbers(slurp(p.poly_mesh.parent_path().parent_path() / "1" / "polyMesh" / "points"));
            // Each list: its size, then the coordinates.
            ASSERT_EQ(ours.size(), 1 + 3 * p.points.size());
            for (std::size_t i = 0; i < p.points.size(); ++i)
                for (std::size_t d = 0; d < 3; ++d)
                    EXPECT_EQ(ours[1 + 3 * i + d], serial[1 + 3 * static_cast<std::size_t>(p.points[i]) + d]);
        }
    }
    // Named in the motion, cyclic patches move as it says, each on its own: a warning says so.
    const auto fixed = write_text(
        dir / "f.json",
        R"({"markers": {"bottomWall": {"translate": [0, 0.001, 0]}, "inout1_half0": "fixed", "inout1_half1": "fixed"}})");
    r = run_cli("deform " + quoted(openfoam_case("channel-cyclic")) + " -m " + quoted(fixed) + " -o " +
                quoted(dir / "fixed/"));
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(r.err.find("the cyclic patches inout1_half0, inout1_half1 are not coupled"), std::string::npos) << r.err;
}
