#pragma once
// Names joined for a message: "a, b, c".
#include <string>
#include <vector>

namespace dgwarp {

/// `names` separated by ", " ("" for none).
inline std::string joined(const std::vector<std::string>& names) {
    std::string s;
    for (const std::string& n : names) s.append(s.empty() ? "" : ", ").append(n);
    return s;
}

}  // namespace dgwarp
