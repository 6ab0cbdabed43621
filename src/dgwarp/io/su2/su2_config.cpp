#include "dgwarp/io/su2/su2_config.hpp"

#include <algorithm>
#include <cctype>
#include <sstream>

#include "dgwarp/core/error.hpp"
#include "dgwarp/io/text_reader.hpp"

namespace dgwarp {

std::vector<Su2ConfigMarker> su2_symmetry_markers(const std::filesystem::path& path) {
    const std::string text = read_file_text(path);
    std::vector<Su2ConfigMarker> markers;
    std::istringstream in(text);
    std::string raw;
    std::size_t line = 0;
    while (std::getline(in, raw)) {
        ++line;
        std::string_view s(raw);
        if (const auto comment = s.find('%'); comment != std::string_view::npos) s = s.substr(0, comment);
        const auto eq = s.find('=');
        if (eq == std::string_view::npos) continue;
        std::string key(trim(s.substr(0, eq)));
        std::transform(key.begin(), key.end(), key.begin(), [](unsigned char c) { return std::toupper(c); });
        if (key != "MARKER_SYM") continue;
        std::string_view value = trim(s.substr(eq + 1));
        if (!value.empty() && value.front() == '(') {
            if (value.back() != ')')
                throw ParseError(path.string(), line, "a list of marker names in parentheses after MARKER_SYM=",
                                 std::string(value));
            value = value.substr(1, value.size() - 2);
        }
        std::size_t start = 0;
        while (start <= value.size()) {
            const auto comma = value.find(',', start);
            const std::string_view name =
                trim(value.substr(start, comma == std::string_view::npos ? std::string_view::npos : comma - start));
            if (!name.empty() && name != "NONE") markers.push_back({std::string(name), line});
            if (comma == std::string_view::npos) break;
            start = comma + 1;
        }
    }
    return markers;
}

}  // namespace dgwarp
