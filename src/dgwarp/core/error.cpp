#include "dgwarp/core/error.hpp"

namespace dgwarp {

std::string ParseError::message(const std::string& file, std::size_t line, const std::string& expected,
                                const std::string& found) {
    std::string m = file;
    if (line) {
        m += ':';
        m += std::to_string(line);
    }
    m += ": expected ";
    m += expected;
    if (!found.empty()) {
        m += ", found '";
        m += found;
        m += "'";
    }
    return m;
}

}  // namespace dgwarp
