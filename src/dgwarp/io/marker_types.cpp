#include "dgwarp/io/marker_types.hpp"

#include <algorithm>

#include "dgwarp/core/joined.hpp"

namespace dgwarp {

std::vector<std::string> marker_types(const Mesh& mesh, const MeshExtras& extras) {
    std::vector<std::string> types(mesh.markers.size());
    if (extras.openfoam && extras.openfoam->patches.size() == types.size())
        for (std::size_t m = 0; m < types.size(); ++m) types[m] = extras.openfoam->patches[m].type;
    if (extras.cgns && extras.cgns->marker_types.size() == types.size()) types = extras.cgns->marker_types;
    return types;
}

bool slides_by_type(std::string_view type) {
    return type == "empty" || type == "wedge" || type == "symmetryPlane" || type == "symmetry" ||
           type == "BCSymmetryPlane";
}

std::vector<std::string> markers_sliding_by_type(const Mesh& mesh, const MeshExtras& extras) {
    const std::vector<std::string> types = marker_types(mesh, extras);
    std::vector<std::string> sliding;
    for (std::size_t m = 0; m < types.size(); ++m)
        if (slides_by_type(types[m])) sliding.push_back(mesh.markers[m].name);
    return sliding;
}

bool is_cyclic_type(std::string_view type) {
    return type == "cyclic" || type == "cyclicAMI" || type == "cyclicACMI" || type == "cyclicSlip";
}

std::string cyclic_neighbour(const OpenFoamPatch& patch) {
    constexpr std::string_view key = "neighbourPatch";
    for (const std::string& e : patch.entries) {
        if (e.compare(0, key.size(), key) != 0 || e.size() <= key.size() || (e[key.size()] != ' ' && e[key.size()] != '\t'))
            continue;
        std::string value = e.substr(key.size());
        const auto first = value.find_first_not_of(" \t");
        const auto last = value.find_last_not_of(" \t;");
        return first == std::string::npos || last < first ? std::string() : value.substr(first, last - first + 1);
    }
    return {};
}

TypedMotion apply_marker_types(const Mesh& mesh, const MeshExtras& extras, MotionSpec& spec,
                               const std::vector<std::string>& also) {
    TypedMotion typed;
    const std::vector<std::string> types = marker_types(mesh, extras);
    // Markers without faces (a wedge case's axis patch) have no node to slide.
    std::vector<std::string> sliding;
    for (std::size_t m = 0; m < types.size(); ++m) {
        const std::string& name = mesh.markers[m].name;
        if ((slides_by_type(types[m]) || std::find(also.begin(), also.end(), name) != also.end()) &&
            !mesh.markers[m].elements.empty())
            sliding.push_back(name);
    }
    typed.sliding = slide_unless_named(spec, sliding);
    // Cyclic pairs: each cyclic patch with its neighbourPatch, once.
    std::vector<std::pair<std::string, std::string>> pairs;
    for (std::size_t m = 0; m < types.size(); ++m) {
        if (!extras.openfoam || (types[m] != "cyclic" && types[m] != "cyclicSlip")) continue;
        const std::string partner = cyclic_neighbour(extras.openfoam->patches[m]);
        for (std::size_t k = m + 1; k < types.size(); ++k)
            if (mesh.markers[k].name == partner && types[k] == types[m] &&
                cyclic_neighbour(extras.openfoam->patches[k]) == mesh.markers[m].name)
                pairs.emplace_back(mesh.markers[m].name, partner);
    }
    typed.coupled = couple_unless_named(spec, pairs);
    for (std::size_t m = 0; m < types.size(); ++m) {
        const std::string& name = mesh.markers[m].name;
        const bool coupled = std::any_of(typed.coupled.begin(), typed.coupled.end(),
                                         [&](const auto& p) { return p.first == name || p.second == name; });
        if (is_cyclic_type(types[m]) && !coupled) typed.uncoupled.push_back(name);
    }
    if (mesh.dim != 3) return typed;
    std::vector<std::size_t> planes;
    std::string axis;
    for (std::size_t m = 0; m < types.size(); ++m) {
        if (types[m] != "empty" && types[m] != "wedge") continue;
        if (mesh.markers[m].elements.empty()) {
            if (axis.empty()) axis = mesh.markers[m].name;
            continue;
        }
        // A plane slides in every frame (named "slide", or made to); one held otherwise keeps the case 3D.
        const bool slides = std::all_of(spec.frames.begin(), spec.frames.end(), [&](const MotionFrame& f) {
            return std::holds_alternative<SlideMotion>(marker_motion(spec, f, mesh.markers[m].name));
        });
        if (!slides) return typed;
        planes.push_back(m);
    }
    if (planes.empty()) return typed;
    PlanarCaseResult found = find_planar_case(mesh, planes, axis.empty() ? "axis" : axis);
    typed.planar = std::move(found.planar);
    typed.not_planar = std::move(found.not_planar);
    return typed;
}

Warning uncoupled_cyclic_warning(const std::vector<std::string>& uncoupled) {
    return {WarningCode::other,
            "the cyclic patches " + joined(uncoupled) +
                " are not coupled (dgwarp couples cyclic and cyclicSlip patches that name each other as "
                "neighbourPatch and that the motion does not name; a cyclicAMI's halves do not share nodes): they "
                "move as the motion says (fixed unless it names them), each on its own, so give both halves the "
                "same motion, or none, for them to still match"};
}

}  // namespace dgwarp
