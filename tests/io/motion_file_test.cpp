#include "dgwarp/io/motion_file.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <numbers>

#include "dgwarp/core/error.hpp"
#include "support/degrees.hpp"
#include "support/test_paths.hpp"

using namespace dgwarp;
using dgwarp::test::deg;

namespace {

MotionSpec parse(const std::string& text) { return parse_motion_file(text, "m.json", test::scratch_dir()); }

/// The ParseError that parsing `text` throws, or fails the test.
ParseError motion_parse_error(const std::string& text) {
    try {
        parse(text);
    } catch (const ParseError& e) {
        return e;
    }
    ADD_FAILURE() << "no ParseError for " << text;
    return ParseError("", 0, "", "");
}

bool contains(const std::string& s, const std::string& part) { return s.find(part) != std::string::npos; }

}  // namespace

// The form the issue fixes, which scripts and tests rely on.
TEST(MotionFile, IssueExampleGivesRotationAboutCenter) {
    const MotionSpec spec = parse(R"({"markers": {"airfoil": {"rotate": {"angle_deg": 45, "axis": [0, 0, 1], "center": [0.25, 0, 0]},
                                                              "translate": [0, 0, 0]},
                                                  "farfield": "fixed"}})");
    ASSERT_EQ(spec.frames.size(), 1u);
    EXPECT_EQ(frame_count(spec), 1u);
    EXPECT_EQ(spec.source, "m.json");
    const auto& markers = spec.frames[0].markers;
    ASSERT_EQ(markers.size(), 2u);
    EXPECT_TRUE(std::holds_alternative<FixedMotion>(markers.at("farfield")));
    const NodeMotion& m = std::get<RigidMotion>(markers.at("airfoil")).motion;
    EXPECT_EQ(m.rotation[0], 0);
    EXPECT_EQ(m.rotation[1], 0);
    EXPECT_DOUBLE_EQ(m.rotation[2], std::numbers::pi / 4);
    EXPECT_EQ(m.center, (Vec3{0.25, 0, 0}));
    EXPECT_EQ(m.translation, (Vec3{0, 0, 0}));
    EXPECT_TRUE(std::holds_alternative<FixedMotion>(spec.default_motion));
    EXPECT_EQ(spec.shared_nodes, SharedNodeRule::moving_wins);
}

TEST(MotionFile, RotateAndTranslateAreEachOptional) {
    const MotionSpec spec = parse(R"({"markers": {"a": {"translate": [2, 2]},
                                                  "b": {"rotate": {"angle_deg": -90, "axis": [0, 0, -2], "center": [1, 2]}}}})");
    const auto& a = std::get<RigidMotion>(spec.frames[0].markers.at("a")).motion;
    EXPECT_EQ(a.translation, (Vec3{2, 2, 0}));
    EXPECT_EQ(a.rotation, (Vec3{0, 0, 0}));
    const auto& b = std::get<RigidMotion>(spec.frames[0].markers.at("b")).motion;
    EXPECT_DOUBLE_EQ(b.rotation[2], std::numbers::pi / 2);  // -90° about -z
    EXPECT_EQ(b.center, (Vec3{1, 2, 0}));
    // The axis defaults to z (2D meshes need none).
    const auto c = parse(R"({"markers": {"c": {"rotate": {"angle_deg": 30, "center": [0, 0]}}}})");
    EXPECT_DOUBLE_EQ(std::get<RigidMotion>(c.frames[0].markers.at("c")).motion.rotation[2], 30 * deg);
}

TEST(MotionFile, DefaultRuleAndTolerance) {
    const MotionSpec spec = parse(R"({"markers": {"far": "fixed"}, "default": {"translate": [0, 1, 0]},
                                      "shared_nodes": "static_wins", "shared_tolerance": 1e-6,
                                      "comment": "all walls move up"})");
    EXPECT_EQ(std::get<RigidMotion>(spec.default_motion).motion.translation, (Vec3{0, 1, 0}));
    EXPECT_EQ(spec.shared_nodes, SharedNodeRule::static_wins);
    EXPECT_EQ(spec.shared_tolerance, 1e-6);
}

TEST(MotionFile, SlideIsAMarkerMotion) {
    const MotionSpec spec = parse(R"({"markers": {"sym": "slide", "wing": {"translate": [0, 0, 1]}}})");
    EXPECT_TRUE(std::holds_alternative<SlideMotion>(spec.frames[0].markers.at("sym")));
    EXPECT_STREQ(motion_kind_name(spec.frames[0].markers.at("sym")), "slide");
    EXPECT_THROW(parse(R"({"markers": {"sym": "slides"}})"), ParseError);
}

TEST(MotionFile, CyclicNamesThePartner) {
    const MotionSpec spec = parse(R"({"markers": {"in": {"cyclic": "out"}, "out": {"cyclic": "in"}}})");
    ASSERT_TRUE(std::holds_alternative<CyclicMotion>(spec.frames[0].markers.at("in")));
    EXPECT_EQ(std::get<CyclicMotion>(spec.frames[0].markers.at("in")).partner, "out");
    EXPECT_STREQ(motion_kind_name(spec.frames[0].markers.at("out")), "cyclic");
    for (const char* bad : {R"({"markers": {"in": {"cyclic": 3}}})", R"({"markers": {"in": {"cyclic": ""}}})",
                            R"({"markers": {"in": {"cyclic": "out", "translate": [0, 1]}}})"}) {
        try {
            parse(bad);
            FAIL() << bad;
        } catch (const ParseError& e) {
            EXPECT_NE(std::string(e.what()).find("markers.in"), std::string::npos) << e.what();
        }
    }
}

TEST(MotionFile, FilesAreReadRelativeToTheMotionFile) {
    const auto dir = test::scratch_dir();
    std::filesystem::create_directories(dir / "sub");
    std::ofstream(dir / "sub" / "d.csv") << "node,dx,dy\n4,0.5,0\n";
    std::ofstream(dir / "sub" / "s.dat") << "4 1 2\n";
    std::ofstream(dir / "sub" / "n.csv") << "4,1,2,0.5,0,0\n";
    std::ofstream(dir / "motion.json") << R"({"markers": {"a": {"displacement_file": "sub/d.csv"},
                                                          "b": {"surface_file": "sub/s.dat"},
                                                          "c": {"node_motion_file": "sub/n.csv"},
                                                          "d": {"displacement_file": "sub/d.csv"}}})";
    const MotionSpec spec = read_motion_file(dir / "motion.json");
    EXPECT_EQ(spec.source, (dir / "motion.json").string());
    const auto& m = spec.frames[0].markers;
    const auto& d = std::get<PrescribedDisplacements>(m.at("a")).displacements;
    EXPECT_EQ(d.nodes, (std::vector<NodeId>{4}));
    EXPECT_EQ(d.values[0], (Vec3{0.5, 0, 0}));
    EXPECT_EQ(std::filesystem::path(d.source), dir / "sub" / "d.csv");
    EXPECT_EQ(std::get<PrescribedPositions>(m.at("b")).positions.values[0], (Vec3{1, 2, 0}));
    EXPECT_EQ(std::get<PrescribedNodeMotions>(m.at("c")).motions.values[0].rotation, (Vec3{0, 0, 0.5}));
    EXPECT_EQ(std::get<PrescribedDisplacements>(m.at("d")).displacements.source, d.source);
    // The files reading it read besides it, each once.
    EXPECT_EQ(motion_named_files(spec), (std::vector<std::filesystem::path>{dir / "sub" / "d.csv", dir / "sub" / "s.dat",
                                                                             dir / "sub" / "n.csv"}));
    EXPECT_TRUE(motion_named_files(parse(R"({"markers": {"a": {"translate": [1, 0]}}})")).empty());
}

TEST(MotionFile, MissingNamedFileSaysWhichFieldNamedIt) {
    try {
        parse(R"({"markers": {"airfoil": {"displacement_file": "nowhere.csv"}}})");
        FAIL();
    } catch (const IoError& e) {
        EXPECT_TRUE(contains(e.what(), "markers.airfoil.displacement_file")) << e.what();
        EXPECT_TRUE(contains(e.file(), "nowhere.csv"));
    }
}

TEST(MotionFile, BadLineInNamedCsvNamesThatFileAndLine) {
    const auto dir = test::scratch_dir();
    std::ofstream(dir / "d.csv") << "node,dx,dy\n1,0,0\n2,0,zero\n";
    try {
        parse_motion_file(R"({"markers": {"a": {"displacement_file": "d.csv"}}})", "m.json", dir);
        FAIL();
    } catch (const ParseError& e) {
        EXPECT_EQ(e.file(), (dir / "d.csv").string());
        EXPECT_EQ(e.line(), 3u);
        EXPECT_EQ(e.found(), "zero");
    }
}

TEST(MotionFile, FramesAreAListOfMarkerMaps) {
    const MotionSpec spec = parse(R"({"frames": [{"markers": {"a": {"translate": [1, 0]}}},
                                                 {"markers": {"a": {"translate": [2, 0]}, "b": "fixed"}},
                                                 {"markers": {}}],
                                      "default": "fixed"})");
    ASSERT_EQ(frame_count(spec), 3u);
    EXPECT_EQ(std::get<RigidMotion>(spec.frames[1].markers.at("a")).motion.translation[0], 2);
    EXPECT_TRUE(spec.frames[2].markers.empty());
    EXPECT_FALSE(spec.time);
}

TEST(MotionFile, PeriodicPitchAndPlunge) {
    const MotionSpec spec = parse(R"({"markers": {"airfoil": {"periodic": {
        "pitch": {"amplitude_deg": 10, "mean_deg": 2, "frequency": 2, "phase_deg": 30, "center": [0.25, 0]},
        "plunge": {"amplitude": [0, 0.5], "frequency": 1, "phase_deg": 90}}}},
      "time": {"time_step": 0.1, "steps": 20}})");
    ASSERT_TRUE(spec.time);
    EXPECT_EQ(spec.time->steps, 20);
    EXPECT_EQ(frame_count(spec), 20u);
    const auto& p = std::get<PeriodicMotion>(spec.frames[0].markers.at("airfoil"));
    ASSERT_TRUE(p.pitch && p.plunge);
    EXPECT_DOUBLE_EQ(p.pitch->amplitude, 10 * deg);
    EXPECT_DOUBLE_EQ(p.pitch->phase, 30 * deg);
    EXPECT_EQ(p.pitch->axis, (Vec3{0, 0, 1}));
    // Step 1 (t = 0.1): angle = 2° + 10° sin(2π·2·0.1 + 30°) = 11.781476°; plunge 0.5 sin(126°) = 0.4045085.
    const NodeMotion m = periodic_motion_at(p, frame_time(spec, 1));
    EXPECT_NEAR(m.rotation[2], 11.781476 * deg, 1e-8);
    EXPECT_NEAR(m.translation[1], 0.4045085, 1e-7);
    // Pitch alone needs no phase, mean or axis.
    const auto alone = parse(R"({"markers": {"w": {"periodic": {"pitch": {"amplitude_deg": 5, "frequency": 1,
                                 "center": [0, 0, 0], "axis": [0, 2, 0]}}}}, "time": {"time_step": 1, "steps": 1}})");
    const auto& pa = std::get<PeriodicMotion>(alone.frames[0].markers.at("w"));
    EXPECT_FALSE(pa.plunge);
    EXPECT_EQ(pa.pitch->axis, (Vec3{0, 1, 0}));
}

TEST(MotionFile, ErrorsNameTheJsonPath) {
    struct Case {
        const char* text;
        const char* in_message;  // the JSON path or the offending key
    };
    const Case cases[] = {
        // Missing fields.
        {R"({"markers": {"airfoil": {"rotate": {"axis": [0, 0, 1], "center": [0, 0]}}}})", "markers.airfoil.rotate.angle_deg"},
        {R"({"markers": {"airfoil": {"rotate": {"angle_deg": 4}}}})", "markers.airfoil.rotate.center"},
        {R"({"frames": [{"markers": {}}, {}]})", "frames[1].markers"},
        {R"({"markers": {"w": {"periodic": {"plunge": {"amplitude": [0, 1]}}}}, "time": {"time_step": 1, "steps": 2}})",
         "markers.w.periodic.plunge.frequency"},
        // Wrong types.
        {R"({"markers": {"airfoil": {"rotate": {"angle_deg": "45", "center": [0, 0]}}}})", "markers.airfoil.rotate.angle_deg"},
        {R"({"markers": {"airfoil": {"translate": [1]}}})", "markers.airfoil.translate"},
        {R"({"markers": {"airfoil": {"translate": [1, 2, 3, 4]}}})", "markers.airfoil.translate"},
        {R"({"markers": {"airfoil": {"translate": [1, null]}}})", "markers.airfoil.translate[1]"},
        {R"({"markers": {"airfoil": "still"}})", "markers.airfoil"},
        {R"({"markers": ["airfoil"]})", "markers"},
        {R"({"markers": {"airfoil": {"displacement_file": 3}}})", "markers.airfoil.displacement_file"},
        // Unknown keys (typos), listing the accepted ones.
        {R"({"markers": {"airfoil": {"translte": [1, 0]}}})", "translte"},
        {R"({"markers": {"airfoil": {"rotate": {"angle": 4, "center": [0, 0]}}}})", "angle_deg"},
        {R"({"marker": {}})", "marker"},
        // Zero axis, bad numbers, bad combinations.
        {R"({"markers": {"airfoil": {"rotate": {"angle_deg": 4, "axis": [0, 0, 0], "center": [0, 0]}}}})",
         "markers.airfoil.rotate.axis"},
        {R"({"markers": {"airfoil": {"rotate": {"angle_deg": 4, "axis": [0, 1], "center": [0, 0]}}}})",
         "markers.airfoil.rotate.axis"},
        {R"({"markers": {"w": {"periodic": {"pitch": {"amplitude_deg": 1, "frequency": 1, "center": [0, 0], "axis": [0, 0, 0]}}}},
             "time": {"time_step": 1, "steps": 2}})", "markers.w.periodic.pitch.axis"},
        {R"({"markers": {"w": {"periodic": {"pitch": {"amplitude_deg": 1, "frequency": -1, "center": [0, 0]}}}},
             "time": {"time_step": 1, "steps": 2}})", "markers.w.periodic.pitch.frequency"},
        {R"({"markers": {"w": {"periodic": {}}}, "time": {"time_step": 1, "steps": 2}})", "markers.w.periodic"},
        {R"({"markers": {"w": {"periodic": {"plunge": {"amplitude": [0, 1], "frequency": 1}}}}, "time": {"time_step": 1, "steps": -3}})",
         "time.steps"},
        {R"({"markers": {"w": {"periodic": {"plunge": {"amplitude": [0, 1], "frequency": 1}}}}, "time": {"time_step": 1, "steps": 0}})",
         "time.steps"},
        {R"({"markers": {"w": {"periodic": {"plunge": {"amplitude": [0, 1], "frequency": 1}}}}, "time": {"time_step": 1, "steps": 2.5}})",
         "time.steps"},
        {R"({"markers": {"w": {"periodic": {"plunge": {"amplitude": [0, 1], "frequency": 1}}}}, "time": {"time_step": 0, "steps": 2}})",
         "time.time_step"},
        {R"({"markers": {"w": {"periodic": {"plunge": {"amplitude": [0, 1], "frequency": 1}}}}})", "time"},
        {R"({"markers": {}, "time": {"time_step": 1, "steps": 2}})", "time"},
        {R"({"frames": [{"markers": {"w": {"periodic": {"plunge": {"amplitude": [0, 1], "frequency": 1}}}}}]})",
         "frames[0].markers.w.periodic"},
        {R"({"markers": {"a": {"translate": [1, 0], "displacement_file": "d.csv"}}})", "markers.a"},
        {R"({"markers": {"a": {}}})", "markers.a"},
        {R"({"markers": {}, "frames": []})", "both"},
        {R"({"default": "fixed"})", "neither"},
        {R"({"frames": []})", "frames"},
        {R"({"markers": {}, "shared_nodes": "moving"})", "shared_nodes"},
        {R"({"markers": {}, "shared_tolerance": -1})", "shared_tolerance"},
        {R"([1, 2])", "top level"},
    };
    for (const Case& c : cases) {
        const ParseError e = motion_parse_error(c.text);
        EXPECT_EQ(e.file(), "m.json");
        EXPECT_TRUE(contains(e.what(), c.in_message)) << "message: " << e.what() << "\nshould name: " << c.in_message;
    }
}

TEST(MotionFile, UnknownKeyListsTheAcceptedKeys) {
    const ParseError e = motion_parse_error(R"({"markers": {"airfoil": {"translte": [1, 0]}}})");
    EXPECT_EQ(e.found(), "unknown key translte");
    EXPECT_TRUE(contains(e.expected(), "translate"));
    EXPECT_TRUE(contains(e.expected(), "rotate"));
    EXPECT_TRUE(contains(e.expected(), "displacement_file"));
    EXPECT_TRUE(contains(e.expected(), "at markers.airfoil"));
}

TEST(MotionFile, SyntaxErrorsNaNAndOverflowGiveTheLine) {
    // NaN is not JSON: the parser stops at it.
    ParseError nan = motion_parse_error("{\"markers\": {\n  \"airfoil\": {\"translate\": [NaN, 0]}\n}}");
    EXPECT_EQ(nan.line(), 2u);
    ParseError missing = motion_parse_error("{\"markers\": {\n\n  \"a\": \"fixed\",\n}}");
    EXPECT_EQ(missing.line(), 4u);
    ParseError overflow = motion_parse_error("{\"markers\": {\n\"a\": {\"translate\": [1e999, 0]}}}");
    EXPECT_EQ(overflow.line(), 2u);
    EXPECT_EQ(overflow.found(), "1e999");
}

TEST(MotionFile, KeyGivenTwiceIsAnError) {
    const ParseError e = motion_parse_error(R"({"frames": [{"markers": {"a": "fixed"}}, {"markers": {"a": "fixed", "a": {"translate": [1, 0]}}}]})");
    EXPECT_TRUE(contains(e.what(), "frames[1].markers.a")) << e.what();
    const ParseError top = motion_parse_error(R"({"markers": {}, "markers": {}})");
    EXPECT_TRUE(contains(top.what(), "key markers twice at markers")) << top.what();
}

TEST(MotionFile, DeeplyNestedJsonIsAParseError) {
    // A million '[' once overflowed the stack (the error message printed the
    // value recursively). Nesting is limited to 100 levels, the top object included.
    const std::size_t n = 1000000;
    const ParseError deep = motion_parse_error("{\"markers\": " + std::string(n, '[') + std::string(n, ']') + "}");
    EXPECT_TRUE(contains(deep.expected(), "arrays and objects nested at most 100 deep")) << deep.what();
    EXPECT_EQ(deep.found().rfind("deeper nesting at markers[0][0]", 0), 0u) << deep.what();
    const auto with_comment = [](std::size_t levels) {
        return R"({"markers": {"a": "fixed"}, "comment": )" + std::string(levels, '[') + std::string(levels, ']') + "}";
    };
    EXPECT_EQ(parse(with_comment(99)).frames.size(), 1u);
    EXPECT_TRUE(contains(motion_parse_error(with_comment(100)).expected(), "nested at most 100 deep"));
}
