#include "dgwarp/methods/option_table.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <set>
#include <string>

#include "dgwarp/core/error.hpp"
#include "dgwarp/methods/dg_harmonic.hpp"
#include "dgwarp/methods/dg_idw.hpp"
#include "dgwarp/methods/rbf.hpp"
#include "support/box_in_box.hpp"

using namespace dgwarp;

TEST(MethodOptionTable, EachOptionBelongsToItsMethodWhateverTheSpelling) {
    EXPECT_EQ(option_method("a-translation"), Method::dg_idw);
    EXPECT_EQ(option_method("--length-scale"), Method::dg_idw);
    EXPECT_EQ(option_method("dg_idw_weights"), Method::dg_idw);
    EXPECT_EQ(option_method("--dgm-substep"), Method::dgm);
    EXPECT_EQ(option_method("idw_static_exponent"), Method::idw);
    EXPECT_EQ(option_method("rbf_greedy"), Method::rbf);
    EXPECT_EQ(option_method("--harmonic-growth"), Method::dg_harmonic);
    EXPECT_EQ(option_method("radius"), std::nullopt);
    EXPECT_EQ(option_method("--method"), std::nullopt);
    EXPECT_EQ(option_method(""), std::nullopt);
    EXPECT_EQ(option_method("a-translationx"), std::nullopt);
}

TEST(MethodOptionTable, NamesAreUniqueAndEveryMethodButNoneIsMissing) {
    std::set<std::string_view> names;
    std::set<Method> methods;
    std::set<std::string_view> keys;
    for (const MethodOption& o : method_option_table) {
        EXPECT_TRUE(names.insert(o.name).second) << o.name;
        EXPECT_TRUE(keys.insert(o.report_key).second) << o.report_key;
        EXPECT_FALSE(o.help.empty()) << o.name;
        EXPECT_EQ(o.name.find('_'), std::string_view::npos) << o.name;  // flags use '-'
        // Its default is a value its own range takes.
        EXPECT_NO_THROW(parse_option_value(o, option_text(o, MethodOptions{}))) << o.name;
        methods.insert(o.method);
    }
    EXPECT_EQ(methods.size(), std::size(all_methods));  // every method has options
}

TEST(MethodOptionTable, TextValuesSetEveryOptionAsTheFlagDoes) {
    MethodOptions o;
    set_method_option(o, "a-translation", "5.5");
    set_method_option(o, "--a-rotation", "2");
    set_method_option(o, "length_scale", "auto");
    set_method_option(o, "dg-idw-weights", "continuous");
    set_method_option(o, "dgm-substep", "on");
    set_method_option(o, "idw-moving-exponent", "4");
    set_method_option(o, "idw-static-exponent", "1.5e0");
    set_method_option(o, "rbf-radius", "0.25");
    set_method_option(o, "rbf-greedy", "1e-3");
    set_method_option(o, "harmonic-wall-spacing", "3");
    set_method_option(o, "harmonic-growth", "0.5");
    set_method_option(o, "harmonic-redo-below", "-1");
    set_method_option(o, "laplacian-increments", "8");
    set_method_option(o, "laplacian-exponent", "2");
    set_method_option(o, "laplacian-model", "laplacian");
    EXPECT_EQ(o.dg_idw.a_translation, 5.5);
    EXPECT_EQ(o.dg_idw.a_rotation, 2.0);
    EXPECT_EQ(o.dg_idw.length_scale, 0.0);  // auto
    EXPECT_EQ(o.dg_idw.weighting, DgIdwWeighting::continuous);
    EXPECT_EQ(o.dgm.on_invalid, DgmOptions::OnInvalidGraph::substep);
    EXPECT_EQ(o.idw.exponent_moving, 4.0);
    EXPECT_EQ(o.idw.exponent_static, 1.5);
    EXPECT_EQ(o.rbf.support_radius, 0.25);
    EXPECT_EQ(o.rbf.greedy_tolerance, 1e-3);
    EXPECT_EQ(o.dg_harmonic.wall_spacing, 3.0);
    EXPECT_EQ(o.dg_harmonic.growth, 0.5);
    EXPECT_EQ(o.dg_harmonic.redo_below, -1.0);
    EXPECT_EQ(o.laplacian.increments, 8);
    EXPECT_EQ(o.laplacian.stiffness_exponent, 2.0);
    EXPECT_EQ(o.laplacian.model, LaplacianModel::laplacian);
    set_method_option(o, "dgm-substep", "false");
    EXPECT_EQ(o.dgm.on_invalid, DgmOptions::OnInvalidGraph::fail);
    set_method_option(o, "length-scale", "2");
    EXPECT_EQ(o.dg_idw.length_scale, 2.0);
}

TEST(MethodOptionTable, TextValuesItCannotTakeNameTheOptionAndTheValue) {
    MethodOptions o;
    const auto message = [&](std::string_view name, std::string_view value) {
        try {
            set_method_option(o, name, value);
        } catch (const Error& e) {
            return std::string(e.what());
        }
        return std::string("no error");
    };
    EXPECT_EQ(message("a-translation", "7x"), "method option a-translation: expected a number from 1e-06 to 1e+06, got '7x'");
    EXPECT_EQ(message("a-translation", ""), "method option a-translation: expected a number from 1e-06 to 1e+06, got ''");
    EXPECT_EQ(message("a-translation", "0"), "method option a-translation: expected a number from 1e-06 to 1e+06, got '0'");
    EXPECT_EQ(message("rbf-radius", "inf"), "method option rbf-radius: expected a number >= 0, got 'inf'");
    EXPECT_EQ(message("rbf-radius", "-0.5"), "method option rbf-radius: expected a number >= 0, got '-0.5'");
    EXPECT_EQ(message("harmonic-growth", "0"), "method option harmonic-growth: expected a positive number, got '0'");
    EXPECT_EQ(message("idw-moving-exponent", "17"),
              "method option idw-moving-exponent: expected a number > 0 and <= 16, got '17'");
    EXPECT_EQ(message("harmonic-redo-below", "0.995"),
              "method option harmonic-redo-below: expected a number from -1 to 0.99, got '0.995'");
    EXPECT_EQ(message("length-scale", "-1"), "method option length-scale: expected a positive number or 'auto', got '-1'");
    EXPECT_EQ(message("dg-idw-weights", "smooth"),
              "method option dg-idw-weights: expected 'paper' or 'continuous', got 'smooth'");
    EXPECT_EQ(message("dgm-substep", "maybe"),
              "method option dgm-substep: expected true or false (on/off, yes/no, 1/0), got 'maybe'");
    EXPECT_EQ(message("laplacian-increments", "2.5"),
              "method option laplacian-increments: expected a whole number from 1 to 64, got '2.5'");
    EXPECT_EQ(message("laplacian-increments", "65"),
              "method option laplacian-increments: expected a whole number from 1 to 64, got '65'");
    EXPECT_TRUE(message("radius", "1").starts_with("unknown method option 'radius'; the method options are a-translation, "))
        << message("radius", "1");
    EXPECT_EQ(o.dg_idw.a_translation, MethodOptions{}.dg_idw.a_translation);  // unchanged by the refusals
}

TEST(MethodOptionTable, RangesAsTheMethodsTakeThem) {
    MethodOptions o;
    set_method_option(o, "rbf-radius", "0");            // 0: global support
    set_method_option(o, "harmonic-redo-below", "-1");  // never
    set_method_option(o, "harmonic-redo-below", "0.99");
    set_method_option(o, "laplacian-exponent", "0");
    set_method_option(o, "idw-static-exponent", "16");
    EXPECT_THROW(set_method_option(o, "idw-static-exponent", "0"), UsageError);
    EXPECT_THROW(set_method_option(o, "laplacian-increments", "0"), UsageError);
    EXPECT_THROW(set_method_option(o, "laplacian-exponent", "4.5"), UsageError);
    EXPECT_THROW(set_method_option(o, "length-scale", "0"), UsageError);  // 0 holds 'auto': written so
}

TEST(MethodOptionTable, EveryOptionReadsBackItsOwnTextExactly) {
    // Defaults, then values whose shortest text is long, 'auto', the other words and switches.
    MethodOptions o;
    EXPECT_EQ(method_options_text(method_options_from_text(method_options_text(o))), method_options_text(o));
    o.dg_idw.a_translation = 0.1 + 0.2;
    o.dg_idw.a_rotation = 1.0 / 3.0;
    o.dg_idw.length_scale = 0;
    o.dg_idw.weighting = DgIdwWeighting::continuous;
    o.dgm.on_invalid = DgmOptions::OnInvalidGraph::substep;
    o.rbf.greedy_tolerance = 2.5e-300;
    o.dg_harmonic.redo_below = -1;
    o.laplacian.increments = 64;
    o.laplacian.model = LaplacianModel::laplacian;
    const std::string text = method_options_text(o);
    const MethodOptions back = method_options_from_text(text);
    EXPECT_EQ(back.dg_idw.a_translation, 0.1 + 0.2);
    EXPECT_EQ(back.dg_idw.a_rotation, 1.0 / 3.0);
    EXPECT_EQ(back.dg_idw.length_scale, 0.0);
    EXPECT_EQ(back.dg_idw.weighting, DgIdwWeighting::continuous);
    EXPECT_EQ(back.dgm.on_invalid, DgmOptions::OnInvalidGraph::substep);
    EXPECT_EQ(back.rbf.greedy_tolerance, 2.5e-300);
    EXPECT_EQ(back.dg_harmonic.redo_below, -1.0);
    EXPECT_EQ(back.laplacian.increments, 64);
    EXPECT_EQ(back.laplacian.model, LaplacianModel::laplacian);
    EXPECT_EQ(method_options_text(back), text);
    EXPECT_NE(text.find("length-scale auto\n"), std::string::npos) << text;
    EXPECT_NE(text.find("dgm-substep true\n"), std::string::npos) << text;
    // Every row: its own text, read back, is the same value.
    for (const MethodOption& row : method_option_table) {
        MethodOptions x = o;
        row.set(x, parse_option_value(row, option_text(row, o)));
        EXPECT_EQ(option_text(row, x), option_text(row, o)) << row.name;
    }
    EXPECT_THROW(method_options_from_text("a-translation\n"), UsageError);
    EXPECT_THROW(method_options_from_text("radius 1\n"), UsageError);
}

TEST(MethodOptionTable, TuningRowsTravelExactlyAndAutoStandsForTheSentinel) {
    MethodOptions o;
    const MethodOption* exponent = find_method_option("harmonic-translation-exponent");
    ASSERT_NE(exponent, nullptr);
    EXPECT_TRUE(exponent->tuning);
    EXPECT_EQ(option_text(*exponent, o), "auto");  // unset: the dimension's default
    set_method_option(o, "harmonic-translation-exponent", "2.75");
    EXPECT_EQ(o.dg_harmonic.translation_exponent, 2.75);
    set_method_option(o, "harmonic_translation_exponent", "auto");
    EXPECT_FALSE(o.dg_harmonic.translation_exponent.has_value());
    EXPECT_THROW(set_method_option(o, "harmonic-translation-exponent", "-1"), UsageError);  // 'auto', not a sentinel
    EXPECT_THROW(set_method_option(o, "harmonic-translation-exponent", "4.5"), UsageError);
    set_method_option(o, "rbf-solver", "sparse");
    EXPECT_EQ(o.rbf.solver, RbfSolver::sparse);
    EXPECT_EQ(expected_values(*find_method_option("rbf-solver")), "'automatic', 'dense' or 'sparse'");
    EXPECT_EQ(expected_values(*exponent), "a number from 0 to 4 or 'auto'");
    // A set value that is not in the range (prepare refuses it) is no 'auto' when it travels.
    o.dg_harmonic.rotation_exponent = -1;
    EXPECT_EQ(method_options_from_text(method_options_text(o)).dg_harmonic.rotation_exponent, -1.0);
    o.dg_harmonic.rotation_exponent.reset();
    // Every field a method reads travels: values no flag takes (NaN, beyond
    // the ranges) come back as they were, for prepare to refuse on every process.
    o.dg_idw.a_translation = std::numeric_limits<double>::quiet_NaN();
    o.laplacian.poisson_ratio = 0.49;
    o.dg_harmonic.redo_max_nodes_3d = 123456789012;
    o.rbf.max_dense_bytes = 1ull << 40;
    o.dgm.max_substeps = 3;
    o.idw.length_scale = 0.125;
    o.dg_harmonic.rigid_gap = 0.75;
    const MethodOptions back = method_options_from_text(method_options_text(o));
    EXPECT_TRUE(std::isnan(back.dg_idw.a_translation));
    EXPECT_EQ(back.laplacian.poisson_ratio, 0.49);
    EXPECT_EQ(back.dg_harmonic.redo_max_nodes_3d, 123456789012);
    EXPECT_EQ(back.rbf.max_dense_bytes, 1ull << 40);
    EXPECT_EQ(back.rbf.solver, RbfSolver::sparse);
    EXPECT_EQ(back.dgm.max_substeps, 3);
    EXPECT_EQ(back.idw.length_scale, 0.125);
    EXPECT_EQ(back.dg_harmonic.rigid_gap, 0.75);
    EXPECT_EQ(method_options_text(back), method_options_text(o));
    EXPECT_THROW(method_options_from_text("laplacian-increments 2.5\n"), UsageError);  // an integer member
}

TEST(MethodOptionTable, APlansKeptOptionsAreItsOwnAndTheRunsTheRest) {
    const test::BoxInBox m = test::box_in_box(2, 8);
    MethodOptions prepared;
    prepared.dg_idw.a_translation = 5;
    prepared.dg_idw.weighting = DgIdwWeighting::continuous;
    prepared.dg_harmonic.wall_spacing = 2.0;
    prepared.dg_harmonic.growth = 0.5;
    prepared.dg_harmonic.rigid_gap = 0.25;
    // The run asks for other values of every option.
    MethodOptions run;
    run.dg_idw.a_translation = 9;
    run.dg_idw.a_rotation = 2;
    run.dg_harmonic.wall_spacing = 3;
    run.dg_harmonic.redo_below = 0.5;
    run.idw.exponent_moving = 4;
    for (Method method : {Method::dg_idw, Method::dg_harmonic}) {
        const Plan plan = prepare(method, m.dim, m.points, m.boundary, prepared);
        const MethodOptions used = options_with_plan(plan, run);
        // What the plan holds of its method's options (its prepare resolved "auto" to values).
        MethodOptions held = run;
        if (const auto* d = std::get_if<DgIdwPlan>(&plan)) held.dg_idw = d->options;
        if (const auto* h = std::get_if<DgHarmonicPlan>(&plan)) held.dg_harmonic = h->options;
        for (const MethodOption& o : method_option_table) {
            SCOPED_TRACE(std::string(method_name(method)) + ": " + std::string(o.name));
            // Kept by the plan: its own; otherwise the run's (its other methods' too).
            const MethodOptions& expected = o.method == method && o.kept_by_plan ? held : run;
            EXPECT_EQ(option_text(o, used), option_text(o, expected));
        }
        if (method == Method::dg_idw) {
            EXPECT_EQ(used.dg_idw.a_translation, 5);
            EXPECT_EQ(used.dg_idw.a_rotation, prepared.dg_idw.a_rotation);  // not the run's 2
            EXPECT_EQ(used.dg_idw.weighting, DgIdwWeighting::continuous);
            EXPECT_EQ(used.dg_harmonic.wall_spacing, 3);
        } else {
            EXPECT_EQ(used.dg_harmonic.wall_spacing, 2);
            EXPECT_EQ(used.dg_harmonic.growth, 0.5);
            EXPECT_EQ(used.dg_harmonic.rigid_gap, 0.25);
            EXPECT_EQ(used.dg_harmonic.redo_below, 0.5);  // the guard acts at step time: the run's
            EXPECT_EQ(used.dg_idw.a_translation, 9);
        }
    }
    // A method whose plan keeps none of its options: the run's, whole.
    const Plan idw = prepare(Method::idw, m.dim, m.points, m.boundary, prepared);
    EXPECT_EQ(method_options_text(options_with_plan(idw, run)), method_options_text(run));
}
