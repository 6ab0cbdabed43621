#pragma once
// Typed access to the fields of a JSON document (nlohmann::ordered_json) for
// the readers of JSON input files. Every error is a ParseError naming the file
// and the JSON path of the bad value (`markers.airfoil.rotate.angle_deg`,
// `frames[2].markers`), what was expected and what was found; syntax errors
// also carry the 1-based line.
#include <cstdint>
#include <initializer_list>
#include <string>
#include <string_view>

#include <nlohmann/json.hpp>

#include "dgwarp/motion/node_motion.hpp"

namespace dgwarp {

using Json = nlohmann::ordered_json;

/// Where a JSON value sits: the file and the path from the document's root
/// ("" for the root itself).
struct JsonPlace {
    std::string file;
    std::string path;

    /// The place of member `key` of this object / element `i` of this array.
    JsonPlace key(std::string_view key) const;
    JsonPlace index(std::size_t i) const;
    /// The path for messages ("the top level" for the root).
    std::string describe() const;
};

/// Parses `text` (the content of `file`). Throws ParseError with the line of a
/// syntax error or of a number too large for a double, and with the path of a
/// key given twice in one object.
Json parse_json_text(const std::string& text, const std::string& file);

/// Throws ParseError("<expected> at <path>", <found: the value, shortened>).
[[noreturn]] void json_fail(const JsonPlace& at, const std::string& expected, const Json& found);

/// Checks `value` is an object whose keys are all in `accepted` (the key
/// "comment" is always accepted, as JSON has no comments); names the unknown
/// key and lists the accepted ones otherwise.
void check_object(const Json& value, const JsonPlace& at, std::initializer_list<std::string_view> accepted);

/// The member `key` of the object `object`; throws ParseError naming the
/// missing field and `what` it should hold.
const Json& require_field(const Json& object, const JsonPlace& at, std::string_view key, std::string_view what);

/// `value` as a finite double / an integer / a string; throws ParseError otherwise.
double finite_number(const Json& value, const JsonPlace& at);
std::int64_t integer(const Json& value, const JsonPlace& at);
std::string string_value(const Json& value, const JsonPlace& at);

/// `value` as an array of 2 or 3 finite numbers (z = 0 for 2); with
/// `three_only`, exactly 3.
Vec3 vector_value(const Json& value, const JsonPlace& at, bool three_only = false);

}  // namespace dgwarp
