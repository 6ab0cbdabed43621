#include "dgwarp/core/warning.hpp"

namespace dgwarp {

std::string_view warning_code_name(WarningCode code) {
    switch (code) {
        case WarningCode::shared_moving_static: return "shared-moving-static";
        case WarningCode::nothing_moves: return "nothing-moves";
        case WarningCode::coincident_boundary_nodes: return "coincident-boundary-nodes";
        case WarningCode::empty_named_marker: return "empty-named-marker";
        case WarningCode::large_rotation: return "large-rotation";
        case WarningCode::large_displacement: return "large-displacement";
        case WarningCode::boundary_folds_faces: return "boundary-folds-faces";
        case WarningCode::conflicting_shared_motions: return "conflicting-shared-motions";
        case WarningCode::outside_hull: return "outside-hull";
        case WarningCode::already_inverted: return "already-inverted";
        case WarningCode::cyclic_mismatch: return "cyclic-mismatch";
        case WarningCode::stale_frames: return "stale-frames";
        case WarningCode::processors_unchanged: return "processors-unchanged";
        case WarningCode::other: return "other";
    }
    return "other";
}

std::vector<std::string> warning_texts(const std::vector<Warning>& warnings) {
    std::vector<std::string> texts;
    texts.reserve(warnings.size());
    for (const Warning& w : warnings) texts.push_back(w.text);
    return texts;
}

}  // namespace dgwarp
