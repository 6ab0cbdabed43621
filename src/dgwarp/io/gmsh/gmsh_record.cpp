#include "dgwarp/io/gmsh/gmsh_record.hpp"

#include <algorithm>
#include <limits>
#include <string>

#include "dgwarp/core/error.hpp"

namespace dgwarp::msh {

void require_record(TextReader& r, std::string_view what) {
    r.require_line(what);
    const std::string_view line = trim(r.line());
    if (line.front() == '$')
        r.fail(std::string(what) + " (the section ended early: a count before it is too large)", line);
}

std::int64_t read_count(TextReader& r, std::string_view what) {
    const std::int64_t n = r.next_int(what);
    if (n < 0) r.fail(std::string(what) + " (a count >= 0)", std::to_string(n));
    return n;
}

int read_int32(TextReader& r, std::string_view what) {
    const std::int64_t v = r.next_int(what);
    if (v < std::numeric_limits<int>::min() || v > std::numeric_limits<int>::max())
        r.fail(std::string(what) + " (a 32-bit integer)", std::to_string(v));
    return static_cast<int>(v);
}

int read_dimension(TextReader& r, std::string_view what) {
    const std::int64_t d = r.next_int(what);
    if (d < 0 || d > 3) r.fail(std::string(what) + " (0, 1, 2 or 3)", std::to_string(d));
    return static_cast<int>(d);
}

void expect_end_of_record(TextReader& r, std::string_view what) {
    const std::string_view extra = r.next_token();
    if (!extra.empty()) r.fail("the end of the line after " + std::string(what), extra);
}

void expect_end_marker(TextReader& r, std::string_view marker) {
    if (!r.next_nonblank_line()) r.fail(marker, "end of file");
    const std::string_view line = trim(r.line());
    if (line != marker) {
        if (line.front() == '$') r.fail(marker, line);
        r.fail(std::string(marker) + " (the section has more lines than its counts say)", line);
    }
}

void fail_at_line(const TextReader& r, std::size_t line, const std::string& expected, const std::string& found) {
    throw ParseError(r.file(), line, expected, found);
}

std::size_t reserve_hint(std::int64_t count, std::size_t file_size, std::size_t min_bytes) {
    return std::min(static_cast<std::size_t>(std::max<std::int64_t>(count, 0)), file_size / min_bytes);
}

}  // namespace dgwarp::msh
