#pragma once
// Small record-level helpers of the Gmsh reader (internal): each reads part of
// a line through TextReader and throws ParseError (file, line, what was
// expected, what was found) when it is not there.
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

#include "dgwarp/io/text_reader.hpp"

namespace dgwarp::msh {

/// Advances to the next non-blank line, which must be a record (not a `$`
/// section line: that means a count above promised more records).
void require_record(TextReader& r, std::string_view what);

/// The next token as a count >= 0.
std::int64_t read_count(TextReader& r, std::string_view what);

/// The next token as an int32 (tags of entities and physical groups).
int read_int32(TextReader& r, std::string_view what);

/// The next token as a dimension 0..3.
int read_dimension(TextReader& r, std::string_view what);

/// Fails when the current line has tokens left (a record longer than expected).
void expect_end_of_record(TextReader& r, std::string_view what);

/// The next non-blank line must be `marker` (e.g. "$EndNodes").
void expect_end_marker(TextReader& r, std::string_view marker);

/// Throws ParseError at `line` (a line other than the current one, such as
/// a section header whose count turned out wrong).
[[noreturn]] void fail_at_line(const TextReader& r, std::size_t line, const std::string& expected,
                               const std::string& found);

/// How many items to reserve for `count` items of at least `min_bytes` bytes
/// of text each: never more than the file could hold, so a corrupt count of
/// 10^12 does not allocate.
std::size_t reserve_hint(std::int64_t count, std::size_t file_size, std::size_t min_bytes);

}  // namespace dgwarp::msh
