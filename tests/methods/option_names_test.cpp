#include "dgwarp/methods/option_names.hpp"

#include <gtest/gtest.h>

#include <set>
#include <string>

#include "dgwarp/core/error.hpp"

using namespace dgwarp;

TEST(MethodOptionNames, EachOptionBelongsToItsMethodWhateverTheSpelling) {
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

TEST(MethodOptionNames, NamesAreUniqueAndEveryMethodButNoneIsMissing) {
    std::set<std::string_view> names;
    std::set<Method> methods;
    for (const MethodOptionName& o : method_option_names) {
        EXPECT_TRUE(names.insert(o.name).second) << o.name;
        EXPECT_EQ(o.name.find('_'), std::string_view::npos) << o.name;  // flags use '-'
        methods.insert(o.method);
    }
    EXPECT_EQ(methods.size(), std::size(all_methods));  // every method has options
}

TEST(MethodOptionNames, TextValuesSetEveryOptionAsTheFlagDoes) {
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

TEST(MethodOptionNames, TextValuesItCannotTakeNameTheOptionAndTheValue) {
    MethodOptions o;
    const auto message = [&](std::string_view name, std::string_view value) {
        try {
            set_method_option(o, name, value);
        } catch (const Error& e) {
            return std::string(e.what());
        }
        return std::string("no error");
    };
    EXPECT_EQ(message("a-translation", "7x"), "method option a-translation: expected a finite number, got '7x'");
    EXPECT_EQ(message("a-translation", ""), "method option a-translation: expected a finite number, got ''");
    EXPECT_EQ(message("rbf-radius", "inf"), "method option rbf-radius: expected a finite number, got 'inf'");
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
