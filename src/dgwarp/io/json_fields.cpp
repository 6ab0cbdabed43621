#include "dgwarp/io/json_fields.hpp"

#include <algorithm>
#include <cmath>
#include <set>
#include <vector>

#include "dgwarp/core/error.hpp"

namespace dgwarp {

namespace {

std::string shorten(std::string s) {
    constexpr std::size_t max = 60;
    return s.size() <= max ? s : s.substr(0, max) + "...";
}

std::size_t line_of_byte(const std::string& text, std::size_t byte) {
    byte = std::min(byte, text.size());
    return 1 + static_cast<std::size_t>(std::count(text.begin(), text.begin() + static_cast<std::ptrdiff_t>(byte), '\n'));
}

/// Deepest nesting of arrays and objects accepted. Input files need a handful
/// of levels; the limit keeps a hostile file (a million '[') from exhausting
/// the stack in code that walks the tree recursively (dump, comparisons).
constexpr std::size_t max_json_depth = 100;

/// Tracks where the parser is, to name the path of a repeated key, and
/// refuses nesting deeper than max_json_depth.
struct KeyTracker {
    struct Level {
        bool array = false;
        std::size_t index = 0;     // arrays: the element being read
        std::string key;           // objects: the member being read
        std::set<std::string> keys;
    };
    std::string file;
    std::vector<Level> stack;

    std::string path() const {
        std::string p;
        for (const Level& l : stack) {
            if (l.array) p += "[" + std::to_string(l.index) + "]";
            else if (!l.key.empty()) p += (p.empty() ? "" : ".") + l.key;
        }
        return p;
    }
    void element_done() {
        if (!stack.empty() && stack.back().array) ++stack.back().index;
    }
    void check_depth() const {
        if (stack.size() > max_json_depth)
            throw ParseError(file, 0, "arrays and objects nested at most " + std::to_string(max_json_depth) + " deep",
                             "deeper nesting at " + shorten(path()));
    }
    bool operator()(int, nlohmann::detail::parse_event_t event, Json& parsed) {
        using E = nlohmann::detail::parse_event_t;
        switch (event) {
            case E::object_start:
                stack.push_back({});
                check_depth();
                break;
            case E::array_start:
                stack.push_back(Level{true, 0, {}, {}});
                check_depth();
                break;
            case E::key: {
                Level& top = stack.back();
                top.key = parsed.get<std::string>();
                if (!top.keys.insert(top.key).second)
                    throw ParseError(file, 0, "each key once in an object", "key " + top.key + " twice at " + path());
                break;
            }
            case E::object_end:
            case E::array_end:
                stack.pop_back();
                element_done();
                break;
            case E::value: element_done(); break;
        }
        return true;
    }
};

std::string type_and_value(const Json& v) {
    if (v.is_null()) return "null";
    return std::string(v.type_name()) + " " + shorten(v.dump());
}

}  // namespace

JsonPlace JsonPlace::key(std::string_view k) const {
    return {file, path.empty() ? std::string(k) : path + "." + std::string(k)};
}

JsonPlace JsonPlace::index(std::size_t i) const { return {file, path + "[" + std::to_string(i) + "]"}; }

std::string JsonPlace::describe() const { return path.empty() ? "the top level" : path; }

Json parse_json_text(const std::string& text, const std::string& file) {
    KeyTracker tracker{file, {}};
    try {
        return Json::parse(text, [&](int depth, nlohmann::detail::parse_event_t e, Json& parsed) {
            return tracker(depth, e, parsed);
        });
    } catch (const Json::parse_error& e) {
        std::string what = e.what();
        // "[json.exception.parse_error.101] parse error at line 3, column 7: syntax error ..."
        const std::size_t colon = what.find(": ");
        if (colon != std::string::npos) what = what.substr(colon + 2);
        throw ParseError(file, line_of_byte(text, e.byte == 0 ? 0 : e.byte - 1), "valid JSON: " + what, "");
    } catch (const Json::out_of_range& e) {
        // "number overflow parsing '1e999'": the only out_of_range the parser throws.
        std::string what = e.what();
        const std::size_t open = what.find('\''), close = what.rfind('\'');
        std::string literal = open != std::string::npos && close > open ? what.substr(open + 1, close - open - 1) : "";
        const std::size_t at = literal.empty() ? std::string::npos : text.find(literal);
        throw ParseError(file, at == std::string::npos ? 0 : line_of_byte(text, at),
                         "a number that fits a double", literal);
    }
}

void json_fail(const JsonPlace& at, const std::string& expected, const Json& found) {
    throw ParseError(at.file, 0, expected + " at " + at.describe(), type_and_value(found));
}

void check_object(const Json& value, const JsonPlace& at, std::initializer_list<std::string_view> accepted) {
    if (!value.is_object()) json_fail(at, "an object", value);
    for (const auto& [k, v] : value.items()) {
        if (k == "comment") continue;
        if (std::find(accepted.begin(), accepted.end(), k) != accepted.end()) continue;
        std::string list;
        for (std::string_view a : accepted) list += (list.empty() ? "" : ", ") + std::string(a);
        throw ParseError(at.file, 0, "one of the keys " + list + " (or comment) at " + at.describe(),
                         "unknown key " + k);
    }
}

const Json& require_field(const Json& object, const JsonPlace& at, std::string_view key, std::string_view what) {
    const auto it = object.find(key);
    if (it == object.end())
        throw ParseError(at.file, 0, "the field " + at.key(key).path + " (" + std::string(what) + ")", "");
    return *it;
}

double finite_number(const Json& value, const JsonPlace& at) {
    if (!value.is_number()) json_fail(at, "a number", value);
    const double v = value.get<double>();
    if (!std::isfinite(v)) json_fail(at, "a finite number", value);
    return v;
}

std::int64_t integer(const Json& value, const JsonPlace& at) {
    if (value.is_number_integer()) return value.get<std::int64_t>();
    // 100.0 is an integer too, for files written by tools that print floats.
    if (value.is_number_float()) {
        const double v = value.get<double>();
        if (std::isfinite(v) && v == std::floor(v) && std::abs(v) < 9e15) return static_cast<std::int64_t>(v);
    }
    json_fail(at, "an integer", value);
}

std::string string_value(const Json& value, const JsonPlace& at) {
    if (!value.is_string()) json_fail(at, "a string", value);
    return value.get<std::string>();
}

Vec3 vector_value(const Json& value, const JsonPlace& at, bool three_only) {
    const char* expected = three_only ? "an array of 3 numbers [x, y, z]" : "an array of 2 or 3 numbers [x, y(, z)]";
    if (!value.is_array() || value.size() > 3 || value.size() < (three_only ? 3u : 2u))
        json_fail(at, expected, value);
    Vec3 v{};
    for (std::size_t i = 0; i < value.size(); ++i) v[i] = finite_number(value[i], at.index(i));
    return v;
}

}  // namespace dgwarp
