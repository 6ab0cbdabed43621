#include "dgwarp/io/marker_names.hpp"

#include <algorithm>
#include <set>

#include "dgwarp/core/error.hpp"
#include "dgwarp/io/mesh_io.hpp"
#include "dgwarp/io/openfoam/openfoam.hpp"

namespace dgwarp {

namespace {

constexpr std::string_view blanks = " \t\n\v\f\r";

std::string trimmed(std::string_view s) {
    const auto first = s.find_first_not_of(blanks);
    if (first == std::string_view::npos) return {};
    return std::string(s.substr(first, s.find_last_not_of(blanks) - first + 1));
}

std::string lower_extension(const std::filesystem::path& p) {
    std::string e = p.extension().string();
    std::transform(e.begin(), e.end(), e.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return e;
}

}  // namespace

std::string marker_rename_problem(std::string_view text) {
    const auto eq = text.rfind('=');
    if (eq == std::string_view::npos) return "expected OLD=NEW, got '" + std::string(text) + "'";
    if (eq == 0 || eq + 1 == text.size()) return "expected a name on each side of '=', got '" + std::string(text) + "'";
    return {};
}

MarkerRename parse_marker_rename(std::string_view text) {
    const auto eq = text.rfind('=');
    return {std::string(text.substr(0, eq)), std::string(text.substr(eq + 1))};
}

void rename_markers(Mesh& mesh, const std::vector<MarkerRename>& renames) {
    for (const MarkerRename& r : renames) {
        const auto index = static_cast<std::size_t>(&find_marker(mesh, r.from) - mesh.markers.data());  // throws naming it
        for (std::size_t m = 0; m < mesh.markers.size(); ++m)
            if (m != index && mesh.markers[m].name == r.to)
                throw MeshError("cannot rename marker '" + r.from + "' to '" + r.to + "': another marker has that name",
                                r.from);
        mesh.markers[index].name = r.to;
    }
}

bool is_openfoam_word(std::string_view name) {
    return !name.empty() && name.find_first_of(" \t\r\n\f\v(){};\"/\\") == std::string_view::npos;
}

std::vector<MarkerRename> make_marker_names_writable(Mesh& mesh, const std::filesystem::path& output) {
    const bool foam = writes_openfoam(output);
    const std::string ext = lower_extension(output);
    const bool cgns = ext == ".cgns", su2 = ext == ".su2";
    if (!foam && !cgns && !su2) return {};
    std::set<std::string> taken;
    for (const Marker& m : mesh.markers) taken.insert(m.name);
    std::vector<MarkerRename> renames;
    for (Marker& m : mesh.markers) {
        std::string name = trimmed(m.name);
        for (char& c : name) {
            const bool bad = foam ? std::string_view(" \t\r\n\f\v(){};\"/\\").find(c) != std::string_view::npos
                                  : cgns ? c == '/' || c == '\0'
                                         : c == '\n' || c == '\r';
            if (bad) c = '_';
        }
        if (cgns && name.size() > 32) name = trimmed(std::string_view(name).substr(0, 32));
        if (name.empty() || (cgns && (name == "." || name == ".."))) name = "marker";
        if (name == m.name) continue;
        std::string unique = name;
        for (int k = 2; taken.count(unique); ++k) {
            std::string suffix(1, '_');  // (not "_" + ...: GCC 12's -Wstringop-overflow false positive)
            suffix += std::to_string(k);
            unique = name;
            if (cgns && unique.size() + suffix.size() > 32) unique.resize(32 - suffix.size());
            unique.append(suffix);
        }
        taken.insert(unique);
        renames.push_back({m.name, unique});
        m.name = unique;
    }
    return renames;
}

}  // namespace dgwarp
