#pragma once
// Numbers as text for the writers: the shortest decimal form that reads back
// to exactly the same double (std::to_chars), so write-then-read is exact.
#include <charconv>
#include <ostream>
#include <string>
#include <system_error>

namespace dgwarp {

inline void write_number(std::ostream& out, double value) {
    char buf[32];
    auto [end, ec] = std::to_chars(buf, buf + sizeof buf, value);
    out.write(buf, end - buf);
}

inline void write_number(std::ostream& out, long long value) {
    char buf[24];
    auto [end, ec] = std::to_chars(buf, buf + sizeof buf, value);
    out.write(buf, end - buf);
}

/// The same text as a string (for messages and help texts).
inline std::string number_text(double value) {
    char buf[32];
    auto [end, ec] = std::to_chars(buf, buf + sizeof buf, value);
    return std::string(buf, end);
}

}  // namespace dgwarp
