// Degenerate boundaries through `dgwarp deform` with every method: empty
// markers (SU2 MARKER_ELEMS= 0, a Gmsh physical group without elements) and
// zero-length boundary edges (a boundary node copied onto another one, as a
// collapsed trailing edge).
#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <nlohmann/json.hpp>

#include "dgwarp/io/mesh_io.hpp"
#include "support/rect_box_files.hpp"
#include "support/test_paths.hpp"

using namespace dgwarp;
using namespace dgwarp::test;

namespace {

bool contains(const std::string& s, const std::string& part) { return s.find(part) != std::string::npos; }

/// Whether some string of the JSON array `warnings` contains `part`.
bool has_warning(const nlohmann::json& warnings, const std::string& part) {
    for (const auto& w : warnings)
        if (contains(w.get<std::string>(), part)) return true;
    return false;
}

std::size_t marker_index(const Mesh& mesh, const std::string& name) {
    for (std::size_t m = 0; m < mesh.markers.size(); ++m)
        if (mesh.markers[m].name == name) return m;
    ADD_FAILURE() << "no marker " << name;
    return 0;
}

/// Appends a copy of node `node` and the zero-length line (node, copy) to marker `marker`; returns the copy's id.
NodeId add_collapsed_edge(Mesh& mesh, NodeId node, const std::string& marker) {
    const auto copy = static_cast<NodeId>(mesh.num_points());
    const auto first = static_cast<std::size_t>(node) * static_cast<std::size_t>(mesh.dim);
    for (int d = 0; d < mesh.dim; ++d) mesh.points.push_back(mesh.points[first + static_cast<std::size_t>(d)]);
    const NodeId edge[] = {node, copy};
    mesh.markers[marker_index(mesh, marker)].elements.push_back(CellType::line, edge);
    return copy;
}

/// The rect-box mesh with a zero-length boundary edge (the rectangle's first
/// node and a copy of it) added to `marker`, and `deform --method all --json`
/// of it with the rect-box rotation.
struct CollapsedEdgeRun {
    Mesh mesh;  // the input: rect-box with the copy
    NodeId node = 0, copy = 0;
    CommandResult deform;
};

CollapsedEdgeRun deform_with_collapsed_edge(const std::string& marker) {
    const auto [dir, rect_box, rotation] = rect_box_files();
    CollapsedEdgeRun run;
    run.mesh = read_mesh(rect_box);
    run.node = run.mesh.markers[marker_index(run.mesh, "rectangle")].elements.nodes[0];
    run.copy = add_collapsed_edge(run.mesh, run.node, marker);
    const auto file = dir / ("collapsed-on-" + marker + ".su2");
    write_mesh(file, run.mesh);
    run.deform = run_cli("deform " + quoted(file) + " -m " + quoted(rotation) + " -o " + quoted(dir / "out.su2") +
                         " --method all --json");
    return run;
}

/// A 2D square of 8 triangles (nodes on a 3 x 3 grid) whose boundary is the
/// physical group "outer"; the physical group "slat" has no element.
const char* gmsh_with_empty_group = R"($MeshFormat
2.2 0 8
$EndMeshFormat
$PhysicalNames
3
1 1 "outer"
1 3 "slat"
2 2 "fluid"
$EndPhysicalNames
$Nodes
9
1 0 0 0
2 1 0 0
3 2 0 0
4 0 1 0
5 1 1 0
6 2 1 0
7 0 2 0
8 1 2 0
9 2 2 0
$EndNodes
$Elements
16
1 1 2 1 1 1 2
2 1 2 1 1 2 3
3 1 2 1 1 3 6
4 1 2 1 1 6 9
5 1 2 1 1 9 8
6 1 2 1 1 8 7
7 1 2 1 1 7 4
8 1 2 1 1 4 1
9 2 2 2 1 1 2 5
10 2 2 2 1 1 5 4
11 2 2 2 1 2 3 6
12 2 2 2 1 2 6 5
13 2 2 2 1 4 5 8
14 2 2 2 1 5 9 8
15 2 2 2 1 5 6 9
16 2 2 2 1 4 8 7
$EndElements
)";

}  // namespace

TEST(CliDegenerate, AnEmptySu2MarkerIsListedAndAMotionNamingItWarnsAndMovesNothing) {
    const auto [dir, rect_box, rotation] = rect_box_files();
    Mesh mesh = read_mesh(rect_box);
    mesh.markers.push_back(Marker{"slat", {}});
    write_mesh(dir / "empty.su2", mesh);
    {
        std::ifstream in(dir / "empty.su2");
        const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
        ASSERT_TRUE(contains(text, "MARKER_TAG= slat\nMARKER_ELEMS= 0\n"));
    }
    const CommandResult info = run_cli("info " + quoted(dir / "empty.su2") + " --json");
    ASSERT_EQ(info.exit_code, 0) << info.err;
    const auto markers = nlohmann::json::parse(info.out).at("mesh").at("markers");
    EXPECT_EQ(markers.back(), (nlohmann::json{{"name", "slat"}, {"elements", 0}, {"nodes", 0}}));

    const auto motion = write_text(dir / "slat.json", R"({"markers": {"slat": {"translate": [0.1, 0]}}})");
    const CommandResult r = run_cli("deform " + quoted(dir / "empty.su2") + " -m " + quoted(motion) + " -o " +
                                    quoted(dir / "out.su2") + " --method all --json");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const auto j = nlohmann::json::parse(r.out);
    EXPECT_TRUE(has_warning(j.at("warnings"), "names marker 'slat', which has no elements")) << j.at("warnings");
    // The same warning as an item a program tests: its code and marker.
    const auto& items = j.at("warning_items");
    EXPECT_TRUE(std::any_of(items.begin(), items.end(), [](const nlohmann::json& w) {
        return w.at("code") == "empty-named-marker" && w.at("marker") == "slat";
    })) << items;
    EXPECT_EQ(j.at("boundary").at("moving_nodes"), 0);
    for (const auto& run : j.at("methods")) {
        EXPECT_TRUE(run.at("valid").get<bool>()) << run.at("method") << run.at("error");
        EXPECT_EQ(read_mesh(run.at("frames").at(0).at("output").get<std::string>()).points, mesh.points)
            << run.at("method");
    }
    // Without --json the warning goes to standard error.
    const CommandResult text = run_cli("deform " + quoted(dir / "empty.su2") + " -m " + quoted(motion) + " -o " +
                                       quoted(dir / "out.su2"));
    EXPECT_EQ(text.exit_code, 0) << text.err;
    EXPECT_TRUE(contains(text.err, "warning: ")) << text.err;
    EXPECT_TRUE(contains(text.err, "'slat', which has no elements")) << text.err;
}

TEST(CliDegenerate, AGmshPhysicalGroupWithoutElementsIsAnEmptyMarker) {
    const auto dir = scratch_dir();
    const auto msh = write_text(dir / "square.msh", gmsh_with_empty_group);
    const CommandResult info = run_cli("info " + quoted(msh) + " --json");
    ASSERT_EQ(info.exit_code, 0) << info.err;
    const auto markers = nlohmann::json::parse(info.out).at("mesh").at("markers");
    ASSERT_EQ(markers.size(), 2u) << markers;
    EXPECT_EQ(markers.at(1), (nlohmann::json{{"name", "slat"}, {"elements", 0}, {"nodes", 0}}));

    const auto motion = write_text(dir / "slat.json", R"({"markers": {"slat": {"translate": [0.1, 0]}}})");
    const CommandResult r = run_cli("deform " + quoted(msh) + " -m " + quoted(motion) + " -o " +
                                    quoted(dir / "out.msh") + " --method all --json");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const auto j = nlohmann::json::parse(r.out);
    EXPECT_TRUE(has_warning(j.at("warnings"), "names marker 'slat'")) << j.at("warnings");
    for (const auto& run : j.at("methods")) EXPECT_TRUE(run.at("valid").get<bool>()) << run.at("method");
}

TEST(CliDegenerate, AMeshWhoseMarkersAreAllEmptyIsAnErrorNamingThem) {
    const auto [dir, rect_box, motion] = rect_box_files();
    Mesh mesh = read_mesh(rect_box);
    for (Marker& m : mesh.markers) m.elements = {};
    write_mesh(dir / "bare.su2", mesh);
    for (const char* method : {"dg-idw", "dgm", "idw", "rbf"}) {
        const CommandResult r = run_cli("deform " + quoted(dir / "bare.su2") + " -m " + quoted(motion) + " -o " +
                                        quoted(dir / "out.su2") + " --method " + method);
        EXPECT_EQ(r.exit_code, 2) << method << ": " << r.err;
        EXPECT_TRUE(contains(r.err, "no boundary nodes")) << method << ": " << r.err;
        EXPECT_TRUE(contains(r.err, "rectangle")) << method << ": " << r.err;
        EXPECT_FALSE(std::filesystem::exists(dir / "out.su2"));
    }
}

TEST(CliDegenerate, AZeroLengthBoundaryEdgeWorksWithEveryMethodAndWarns) {
    const auto [mesh, node, copy, r] = deform_with_collapsed_edge("rectangle");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const auto j = nlohmann::json::parse(r.out);
    EXPECT_TRUE(has_warning(j.at("warnings"), "2 boundary nodes are at the same coordinates")) << j.at("warnings");
    EXPECT_TRUE(has_warning(j.at("warnings"),
                            "nodes " + std::to_string(node) + " and " + std::to_string(copy)))
        << j.at("warnings");
    const auto& items = j.at("warning_items");
    const auto example = node;  // not the structured binding: older clang cannot capture one
    EXPECT_TRUE(std::any_of(items.begin(), items.end(), [&](const nlohmann::json& w) {
        return w.at("code") == "coincident-boundary-nodes" && w.at("count") == 2 && w.at("node") == example;
    })) << items;
    for (const auto& run : j.at("methods")) {
        SCOPED_TRACE(run.at("method").get<std::string>());
        EXPECT_TRUE(run.at("valid").get<bool>()) << run.at("error");
        EXPECT_TRUE(run.at("frames").at(0).at("warnings").empty());
        const Mesh out = read_mesh(run.at("frames").at(0).at("output").get<std::string>());
        // The copy moved with the node: the edge stays of zero length.
        for (int d = 0; d < 2; ++d) EXPECT_EQ(out.points[2 * copy + d], out.points[2 * node + d]);
        EXPECT_NE(out.points[2 * node], mesh.points[2 * node]);
    }
}

TEST(CliDegenerate, CoincidentNodesOnAMovingAndAStaticMarkerSeparateWithAWarning) {
    // The edge (node, copy) on the static far field: node is then on both markers and moves
    // (moving_wins), its copy is static only: a collapsed trailing edge whose lower node is held.
    const auto [mesh, node, copy, r] = deform_with_collapsed_edge("farfield");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const auto j = nlohmann::json::parse(r.out);
    for (const auto& run : j.at("methods")) {
        const std::string method = run.at("method");
        SCOPED_TRACE(method);
        const auto& frame = run.at("frames").at(0);
        // IDW and laplacian keep every node apart (no graph vertex stands for two): no group to warn of.
        EXPECT_EQ(has_warning(frame.at("warnings"), "1 group of boundary nodes at the same coordinates was given different motions"),
                  method != "idw" && method != "laplacian")
            << frame.at("warnings");
        EXPECT_EQ(frame.at("warning_items").size(), frame.at("warnings").size());
        for (const auto& w : frame.at("warning_items")) {
            EXPECT_EQ(w.at("code"), "conflicting-shared-motions") << w;
            EXPECT_EQ(w.at("count"), 1) << w;
        }
        const Mesh out = read_mesh(frame.at("output").get<std::string>());
        EXPECT_EQ(out.points[2 * copy], mesh.points[2 * copy]);  // static
        EXPECT_NE(out.points[2 * node], mesh.points[2 * node]);  // moved
    }
}

TEST(CliDegenerate, VolumeNodesOutsideTheGraphsHullAreAWarning) {
    // Without its far-field marker, the rectangle's graph covers none of the volume nodes.
    const auto [dir, rect_box, rotation] = rect_box_files();
    Mesh mesh = read_mesh(rect_box);
    mesh.markers.erase(mesh.markers.begin() + static_cast<std::ptrdiff_t>(marker_index(mesh, "farfield")));
    write_mesh(dir / "open.su2", mesh);
    const auto motion = write_text(dir / "translate.json", R"({"markers": {"rectangle": {"translate": [0.01, 0]}}})");
    const std::string inputs = quoted(dir / "open.su2") + " -m " + quoted(motion);
    const CommandResult r = run_cli("deform " + inputs + " -o " + quoted(dir / "out.su2") + " --json");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const auto j = nlohmann::json::parse(r.out);
    EXPECT_GT(j.at("plan").at("outside_hull").get<long>(), 0);
    EXPECT_TRUE(has_warning(j.at("warnings"), std::to_string(j.at("plan").at("outside_hull").get<long>()) +
                                                  " volume nodes are outside the Delaunay graph's hull"))
        << j.at("warnings");
    const CommandResult text = run_cli("deform " + inputs + " -o " + quoted(dir / "out.su2"));
    EXPECT_TRUE(contains(text.err, "warning: ")) << text.err;
    EXPECT_TRUE(contains(text.err, "outside the Delaunay graph's hull")) << text.err;
    const CommandResult prepared = run_cli("prepare " + inputs + " -o " + quoted(dir / "open.plan") + " --json");
    ASSERT_EQ(prepared.exit_code, 0) << prepared.err;
    EXPECT_TRUE(has_warning(nlohmann::json::parse(prepared.out).at("warnings"), "outside the Delaunay graph's hull"));
    // With the far field, no node is outside: no such warning.
    const CommandResult closed = run_cli("deform " + quoted(rect_box) + " -m " + quoted(motion) + " -o " +
                                         quoted(dir / "out.su2") + " --json");
    ASSERT_EQ(closed.exit_code, 0) << closed.err;
    EXPECT_FALSE(has_warning(nlohmann::json::parse(closed.out).at("warnings"), "hull"));
}

// #17 item 4: cells that were already bad in the input are reported as such,
// never blamed on the motion, and do not make a valid step invalid.
namespace {

/// The rect-box mesh with one extra, zero-area triangle on three consecutive
/// far-field nodes of its bottom side (y = -20); returns its file.
std::filesystem::path rect_box_with_degenerate_cell(const RectBoxFiles& files) {
    Mesh mesh = read_mesh(files.mesh);
    std::vector<NodeId> bottom;
    for (NodeId n : marker_nodes(find_marker(mesh, "farfield")))
        if (mesh.points[2 * static_cast<std::size_t>(n) + 1] == -20) bottom.push_back(n);
    std::sort(bottom.begin(), bottom.end(), [&](NodeId a, NodeId b) { return mesh.points[2 * a] < mesh.points[2 * b]; });
    EXPECT_GE(bottom.size(), 3u);
    const NodeId flat[] = {bottom[0], bottom[1], bottom[2]};
    mesh.cells.push_back(CellType::triangle, flat);
    const auto file = files.dir / "degenerate.su2";
    write_mesh(file, mesh);
    return file;
}

/// The rect-box mesh with the node order of cell 0 reversed (the cell flipped).
std::filesystem::path rect_box_with_flipped_cell(const RectBoxFiles& files) {
    Mesh mesh = read_mesh(files.mesh);
    const auto begin = mesh.cells.nodes.begin() + mesh.cells.offsets[0];
    std::reverse(begin, mesh.cells.nodes.begin() + mesh.cells.offsets[1]);
    const auto file = files.dir / "flipped.su2";
    write_mesh(file, mesh);
    return file;
}

}  // namespace

TEST(CliDegenerate, ACellDegenerateInTheInputIsReportedAndDoesNotMakeAStepInvalid) {
    const RectBoxFiles files = rect_box_files();
    const auto mesh = rect_box_with_degenerate_cell(files);
    const auto still = write_text(files.dir / "still.json", R"({"markers": {"rectangle": {"translate": [0, 0]}}})");
    for (const auto& motion : {still, files.motion}) {
        const CommandResult r = run_cli("deform " + quoted(mesh) + " -m " + quoted(motion) + " -o " +
                                        quoted(files.dir / "out.su2") + " --json");
        ASSERT_EQ(r.exit_code, 0) << motion << ": " << r.err;
        const auto j = nlohmann::json::parse(r.out);
        EXPECT_TRUE(j.at("valid").get<bool>());
        EXPECT_EQ(j.at("original_quality").at("inverted"), 1);
        const auto& frame = j.at("frames")[0];
        EXPECT_EQ(frame.at("quality").at("inverted"), 1);  // still there, and counted
        EXPECT_EQ(frame.at("inverted_by_motion"), 0);
        EXPECT_TRUE(frame.at("worst_inverted_cells").empty());
        EXPECT_TRUE(has_warning(j.at("warnings"), "already inverted or degenerate in the input mesh")) << j.at("warnings");
    }
    // The text report says which cells the motion inverted.
    const CommandResult text =
        run_cli("deform " + quoted(mesh) + " -m " + quoted(still) + " -o " + quoted(files.dir / "out.su2"));
    EXPECT_NE(text.out.find("inverted by the motion 0 (the other 1 were already inverted or degenerate in the input)"),
              std::string::npos)
        << text.out;
    EXPECT_NE(text.err.find("1 cell is already inverted or degenerate in the input mesh"), std::string::npos) << text.err;
    // A motion that does invert cells is still invalid, and only its own cells are counted.
    const auto huge = write_text(files.dir / "huge.json", R"({"markers": {"rectangle": {"translate": [18.8, 0]}}})");
    const CommandResult bad = run_cli("deform " + quoted(mesh) + " -m " + quoted(huge) + " -o " +
                                      quoted(files.dir / "bad.su2") + " --json");
    EXPECT_EQ(bad.exit_code, 3);
    const auto bad_json = nlohmann::json::parse(bad.out);
    const auto& frame = bad_json.at("frames")[0];
    EXPECT_GT(frame.at("inverted_by_motion").get<int>(), 0);
    EXPECT_EQ(frame.at("quality").at("inverted").get<int>(), frame.at("inverted_by_motion").get<int>() + 1);
    const auto worst = frame.at("worst_inverted_cells").get<std::vector<std::int64_t>>();
    const auto degenerate_cell = static_cast<std::int64_t>(read_mesh(mesh).cells.size() - 1);
    EXPECT_EQ(std::count(worst.begin(), worst.end(), degenerate_cell), 0);
    EXPECT_FALSE(std::filesystem::exists(files.dir / "bad.su2"));
}

TEST(CliDegenerate, ACellFlippedInTheInputCountsAsInvertedBeforeAndAfterAsInInfo) {
    const RectBoxFiles files = rect_box_files();
    const auto mesh = rect_box_with_flipped_cell(files);
    const CommandResult info = run_cli("info " + quoted(mesh) + " --json");
    ASSERT_EQ(info.exit_code, 0) << info.err;
    EXPECT_EQ(nlohmann::json::parse(info.out).at("quality").at("inverted"), 1);
    const CommandResult r = run_cli("deform " + quoted(mesh) + " -m " + quoted(files.motion) + " -o " +
                                    quoted(files.dir / "out.su2") + " --json");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const auto j = nlohmann::json::parse(r.out);
    EXPECT_EQ(j.at("original_quality").at("inverted"), 1);  // as info says
    EXPECT_EQ(j.at("frames")[0].at("quality").at("inverted"), 1);
    EXPECT_EQ(j.at("frames")[0].at("inverted_by_motion"), 0);
    EXPECT_TRUE(j.at("valid").get<bool>());
}
