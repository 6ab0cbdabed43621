// The common interface: every method is reachable by name. (What every method
// does through the interface: method_properties_test.cpp.)
#include "dgwarp/methods/method.hpp"

#include <gtest/gtest.h>

using namespace dgwarp;

TEST(Method, NamesRoundTrip) {
    for (Method m : all_methods) {
        const auto back = method_from_name(method_name(m));
        ASSERT_TRUE(back.has_value()) << method_name(m);
        EXPECT_EQ(*back, m);
    }
    EXPECT_FALSE(method_from_name("spring").has_value());
}
