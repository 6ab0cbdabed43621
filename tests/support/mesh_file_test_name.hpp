#pragma once
// The name of a test parameterised by a mesh file: the file's stem with every
// character that is not a letter or digit replaced by '_' (gtest's rule).
#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <string>

namespace dgwarp::test {

inline std::string mesh_file_test_name(const ::testing::TestParamInfo<std::filesystem::path>& info) {
    std::string s = info.param.stem().string();
    std::replace_if(s.begin(), s.end(), [](char c) { return !std::isalnum(static_cast<unsigned char>(c)); }, '_');
    return s;
}

}  // namespace dgwarp::test
