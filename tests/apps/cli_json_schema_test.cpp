// Every --json report validates against its schema in docs/schema/ (checked
// by tests/tools/check_json_schema.py with Debian's python3-jsonschema), and
// a tampered report does not: the schemas are strict enough to catch a
// renamed, missing or retyped field.
#include <gtest/gtest.h>

#include "dgwarp/methods/method.hpp"

#include <fstream>
#include <functional>
#include <nlohmann/json.hpp>
#include <sstream>

#include "support/rect_box_files.hpp"
#include "support/test_paths.hpp"

using namespace dgwarp::test;

namespace {

/// Validates `report` (JSON text, written to a file in `dir`) against docs/schema/COMMAND.schema.json.
CommandResult validate(const std::filesystem::path& dir, const std::string& command, const std::string& report) {
    const auto file = write_text(dir / ("report-" + command + ".json"), report);
    return run_command(std::string(DGWARP_PYTHON) + " " + quoted(source_dir() / "tests/tools/check_json_schema.py") +
                       " " + quoted(source_dir() / "docs/schema") + " " + command + " " + quoted(file));
}

/// Runs the CLI, expects exit 0, validates its standard output against COMMAND's schema.
nlohmann::json valid_report(const std::filesystem::path& dir, const std::string& command, const std::string& args) {
    const CommandResult r = run_cli(command + " " + args);
    EXPECT_EQ(r.exit_code, 0) << r.err;
    const CommandResult v = validate(dir, command, r.out);
    EXPECT_EQ(v.exit_code, 0) << command << " " << args << ":\n" << v.err << "\n" << r.out;
    return nlohmann::json::parse(r.out);
}

/// `report` changed by `tamper` must fail validation, the message naming `expected`.
void expect_invalid(const std::filesystem::path& dir, const std::string& command, nlohmann::json report,
                    const std::function<void(nlohmann::json&)>& tamper, const std::string& expected) {
    tamper(report);
    const CommandResult v = validate(dir, command, report.dump());
    EXPECT_EQ(v.exit_code, 1) << command << ": a tampered report passed (expected an error about " << expected << ")";
    EXPECT_NE(v.err.find(expected), std::string::npos) << v.err;
}

}  // namespace

TEST(CliJsonSchema, EverySchemaIsValidAndTheToolRejectsBadUsage) {
    // A report for a command without a schema file, and no arguments: usage errors (2), not "valid".
    const auto dir = scratch_dir();
    EXPECT_EQ(validate(dir, "no-such-command", "{}").exit_code, 2);
    EXPECT_EQ(run_command(std::string(DGWARP_PYTHON) + " " + quoted(source_dir() / "tests/tools/check_json_schema.py"))
                  .exit_code,
              2);
    EXPECT_EQ(validate(dir, "info", "not json").exit_code, 1);
}

TEST(CliJsonSchema, InfoAndQualityReportsValidateAndTamperedOnesDoNot) {
    const RectBoxFiles c = rect_box_files();
    const nlohmann::json info = valid_report(c.dir, "info", quoted(c.mesh) + " --json");
    valid_report(c.dir, "quality", quoted(c.mesh) + " --json");
    const nlohmann::json quality = valid_report(c.dir, "quality", quoted(c.mesh) + " --reference " + quoted(c.mesh) + " --json");
    ASSERT_TRUE(quality.contains("ratio"));

    expect_invalid(c.dir, "info", info, [](auto& j) { j["mesh"]["node_count"] = j["mesh"]["nodes"]; j["mesh"].erase("nodes"); },
                   "node_count");
    expect_invalid(c.dir, "info", info, [](auto& j) { j.erase("bounding_box"); }, "bounding_box");
    expect_invalid(c.dir, "info", info, [](auto& j) { j["quality"]["min"] = "0.5"; }, "quality/min");
    expect_invalid(c.dir, "info", info, [](auto& j) { j["quality"]["histogram"]["counts"].push_back(0); }, "counts");
    expect_invalid(c.dir, "info", info, [](auto& j) { j["schema_version"] = 1; }, "schema_version");
    expect_invalid(c.dir, "info", info, [](auto& j) { j["mesh"]["markers"][0].erase("elements"); }, "elements");
    expect_invalid(c.dir, "quality", quality, [](auto& j) { j.erase("ratio"); }, "ratio");
    expect_invalid(c.dir, "quality", quality, [](auto& j) { j["ratio"]["worst"] = 0; }, "worst");
    // A mesh of polyhedra (snappyHexMesh's, tests/data/openfoam) names its cell types too.
    const nlohmann::json poly =
        valid_report(c.dir, "info", quoted(source_dir() / "tests/data/openfoam/snappy-sphere") + " --json");
    EXPECT_EQ(poly["mesh"]["cell_types"]["polyhedron"], 272);
    expect_invalid(c.dir, "info", poly, [](auto& j) { j["mesh"]["cell_types"]["polytope"] = 1; }, "polytope");
}

TEST(CliJsonSchema, DeformAndPrepareReportsValidateAndTamperedOnesDoNot) {
    const RectBoxFiles c = rect_box_files();
    const std::string inputs = quoted(c.mesh) + " -m " + quoted(c.motion);
    const nlohmann::json one = valid_report(c.dir, "deform", inputs + " -o " + quoted(c.dir / "out.su2") + " --json");
    const nlohmann::json all =
        valid_report(c.dir, "deform", inputs + " -o " + quoted(c.dir / "cmp.su2") + " --method all --json");
    ASSERT_EQ(all.at("methods").size(), std::size(dgwarp::all_methods));
    const nlohmann::json prepared =
        valid_report(c.dir, "prepare", inputs + " --method dg-idw -o " + quoted(c.dir / "m.plan") + " --json");
    valid_report(c.dir, "prepare", inputs + " -o " + quoted(c.dir / "h.plan") + " --json");  // the default: dg-harmonic
    const nlohmann::json planned =
        valid_report(c.dir, "deform", inputs + " --plan " + quoted(c.dir / "m.plan") + " -o " + quoted(c.dir / "p.su2") + " --json");
    // A loaded DG-IDW plan keeps only the graph simplices that hold a volume node.
    EXPECT_TRUE(planned.at("plan").at("graph_simplices").is_null());
    EXPECT_EQ(planned.at("plan").at("graph_simplices_used"), prepared.at("plan").at("graph_simplices_used"));
    // A time series, and a motion far larger than the mesh (a warning; cells invert: exit 3, report on stdout).
    const auto pitch = write_text(c.dir / "pitch.json", R"({
        "markers": {"rectangle": {"periodic": {"pitch": {"amplitude_deg": 5, "frequency": 1, "center": [0, 0]}}}},
        "time": {"time_step": 0.25, "steps": 3}})");
    const nlohmann::json series = valid_report(
        c.dir, "deform", quoted(c.mesh) + " -m " + quoted(pitch) + " -o " + quoted(c.dir / "f.su2") + " --json");
    EXPECT_EQ(series.at("frames").size(), 3u);
    const auto huge = write_text(c.dir / "huge.json", R"({"markers": {"rectangle": {"translate": [60, 0]}}})");
    const CommandResult r = run_cli("deform " + quoted(c.mesh) + " -m " + quoted(huge) + " -o " +
                                    quoted(c.dir / "h.su2") + " --json");
    EXPECT_EQ(r.exit_code, 3) << r.err;
    const CommandResult v = validate(c.dir, "deform", r.out);
    EXPECT_EQ(v.exit_code, 0) << v.err;
    EXPECT_FALSE(nlohmann::json::parse(r.out).at("warnings").empty());
    // The same with --untangle: the frame carries what the repair did.
    const CommandResult ru = run_cli("deform " + quoted(c.mesh) + " -m " + quoted(huge) + " -o " +
                                     quoted(c.dir / "u.su2") + " --untangle --allow-invalid --json");
    ASSERT_EQ(ru.exit_code, 0) << ru.err;
    const nlohmann::json untangled = nlohmann::json::parse(ru.out);
    EXPECT_EQ(validate(c.dir, "deform", ru.out).exit_code, 0);
    ASSERT_TRUE(untangled.at("frames").at(0).at("untangle").is_object());
    expect_invalid(c.dir, "deform", untangled, [](auto& j) { j["frames"][0]["untangle"].erase("nodes_moved"); },
                   "nodes_moved");
    expect_invalid(c.dir, "deform", one, [](auto& j) { j["frames"][0].erase("untangle"); }, "untangle");

    expect_invalid(c.dir, "deform", one, [](auto& j) { j.erase("plan"); }, "plan");
    expect_invalid(c.dir, "deform", one, [](auto& j) { j["frames"][0]["seconds"].erase("deform"); }, "deform");
    expect_invalid(c.dir, "deform", one, [](auto& j) { j["boundary"]["moving"] = j["boundary"]["moving_nodes"]; }, "moving");
    expect_invalid(c.dir, "deform", one, [](auto& j) { j["method"] = "spring"; }, "spring");
    expect_invalid(c.dir, "deform", one, [](auto& j) { j["methods"] = nlohmann::json::array(); }, "methods");
    expect_invalid(c.dir, "deform", all, [](auto& j) { j["methods"][1]["plan"].erase("outside_hull"); }, "outside_hull");
    expect_invalid(c.dir, "deform", all, [](auto& j) { j["methods"][0]["plan"].erase("graph_simplices_used"); },
                   "graph_simplices_used");
    expect_invalid(c.dir, "deform", one, [](auto& j) { j["plan"]["graph_simplices"] = "many"; }, "graph_simplices");
    expect_invalid(c.dir, "deform", all, [](auto& j) { j["method"] = "dg-idw"; }, "method");
    expect_invalid(c.dir, "prepare", prepared, [](auto& j) { j["seconds"].erase("write"); }, "write");
    expect_invalid(c.dir, "prepare", prepared, [](auto& j) { j["options"]["length_scale"] = "big"; }, "length_scale");
}

TEST(CliJsonSchema, CheckReportValidatesAndATamperedOneDoesNot) {
    const RectBoxFiles c = rect_box_files();
    const nlohmann::json one = valid_report(c.dir, "check", quoted(c.mesh) + " -m " + quoted(c.motion) + " --json");
    EXPECT_EQ(one.at("frames"), 1);
    // A time series with a warning in every frame (a motion far larger than the mesh).
    const auto series = write_text(c.dir / "series.json", R"({
        "markers": {"rectangle": {"periodic": {"plunge": {"amplitude": [100, 0], "frequency": 1, "phase_deg": 90}}}},
        "time": {"time_step": 0.25, "steps": 3}})");
    const nlohmann::json three = valid_report(c.dir, "check", quoted(c.mesh) + " -m " + quoted(series) + " --json");
    EXPECT_EQ(three.at("frames"), 3);
    EXPECT_EQ(three.at("warnings").size(), 2u);  // frames 0 and 2 (sin 90°, sin 270°; frame 1 is at about 0)
    expect_invalid(c.dir, "check", one, [](auto& j) { j.erase("frames"); }, "frames");
    expect_invalid(c.dir, "check", one, [](auto& j) { j["seconds"].erase("resolve"); }, "resolve");
    expect_invalid(c.dir, "check", one, [](auto& j) { j["options"] = nlohmann::json::object(); }, "options");
}

TEST(CliJsonSchema, BenchReportValidatesAndATamperedOneDoesNot) {
    const auto dir = scratch_dir(), js = dir / "bench.json";
    const CommandResult r = run_cli("bench --case rect-box --json " + quoted(js));
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const std::string text = slurp(js);
    const CommandResult v = validate(dir, "bench", text);
    EXPECT_EQ(v.exit_code, 0) << v.err;
    expect_invalid(dir, "bench", nlohmann::json::parse(text), [](auto& j) { j["rows"][0]["methods"][0].erase("paper"); },
                   "paper");
}

TEST(CliJsonSchema, AMultiZoneSu2FileSaysWhichZoneIsRead) {
    // Issue #27: zone 1 of a multi-zone file was read silently by info
    // (text and JSON) and deform.
    const auto dir = scratch_dir();
    const std::string zone = "NDIME= 2\nNELEM= 2\n5 0 1 2\n5 0 2 3\nNPOIN= 4\n0 0\n1 0\n1 1\n0 1\n"
                             "NMARK= 2\nMARKER_TAG= wall\nMARKER_ELEMS= 1\n3 0 1\n"
                             "MARKER_TAG= farfield\nMARKER_ELEMS= 3\n3 1 2\n3 2 3\n3 3 0\n";
    const auto mesh = write_text(dir / "zones.su2", "NZONE= 2\nIZONE= 1\n" + zone + "IZONE= 2\n" + zone);
    const nlohmann::json info = valid_report(dir, "info", quoted(mesh) + " --json");
    EXPECT_EQ(info.at("zone"), (nlohmann::json{{"number", 1}, {"of", 2}}));
    EXPECT_EQ(valid_report(dir, "info", quoted(mesh) + " --zone 2 --json").at("zone").at("number"), 2);
    const CommandResult text = run_cli("info " + quoted(mesh));
    EXPECT_NE(text.out.find("zone 1 of 2 (--zone N reads another)"), std::string::npos) << text.out;
    const auto motion = write_text(dir / "m.json", R"({"markers": {"wall": {"translate": [0, 0]}}})");
    const CommandResult deform = run_cli("deform " + quoted(mesh) + " -m " + quoted(motion) + " -o " + quoted(dir / "o.su2"));
    EXPECT_EQ(deform.exit_code, 0) << deform.err;
    EXPECT_NE(deform.err.find("zones.su2 holds 2 zones; zone 1 is read"), std::string::npos) << deform.err;
    // A single-zone file: 1 of 1, no warning.
    const auto single = write_text(dir / "single.su2", zone);
    EXPECT_EQ(valid_report(dir, "info", quoted(single) + " --json").at("zone").at("of"), 1);
}
