#include "dgwarp/methods/option_names.hpp"

#include <gtest/gtest.h>

#include <set>
#include <string>

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
