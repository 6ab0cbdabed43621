#pragma once
// Shared by the CGNS reading tests.
#include <gtest/gtest.h>

#include <exception>
#include <filesystem>
#include <string>
#include <vector>

#include "dgwarp/io/cgns/cgns.hpp"

namespace dgwarp::test {

/// Reading `file` throws E whose message contains every one of `parts`.
template <class E>
void expect_cgns_error(const std::filesystem::path& file, const std::vector<std::string>& parts) {
    try {
        read_cgns(file);
        ADD_FAILURE() << "no error reading " << file;
    } catch (const E& e) {
        for (const std::string& p : parts) EXPECT_NE(std::string(e.what()).find(p), std::string::npos) << e.what();
    } catch (const std::exception& e) {
        ADD_FAILURE() << "another error: " << e.what();
    }
}

}  // namespace dgwarp::test
