#include "dgwarp/run/report_json.hpp"

#include <cmath>

#include "dgwarp/methods/option_table.hpp"

namespace dgwarp {

nlohmann::json quality_json(const QualitySummary& q) {
    return {{"cells", q.cells},
            {"min", q.min},
            {"mean", q.mean},
            {"inverted", q.inverted},
            {"worst_cell", q.worst_cell},
            {"histogram", {{"edges", q.histogram.edges}, {"counts", q.histogram.counts}}}};
}

nlohmann::json ratio_json(const RatioSummary& r) {
    return {{"min", r.min}, {"mean", r.mean}, {"worst_cell", r.worst_cell}};
}

nlohmann::json warning_json(const Warning& w, const std::string& method) {
    nlohmann::json j = {{"code", warning_code_name(w.code)}, {"text", w.text}};
    if (!w.marker.empty()) j["marker"] = w.marker;
    if (w.count >= 0) j["count"] = w.count;
    if (w.node >= 0) j["node"] = w.node;
    if (w.element >= 0) j["element"] = w.element;
    if (!std::isnan(w.value)) j["value"] = w.value;
    if (!method.empty()) j["method"] = method;
    return j;
}

nlohmann::json warning_texts_json(const std::vector<Warning>& warnings) {
    nlohmann::json j = nlohmann::json::array();
    for (const Warning& w : warnings) j.push_back(w.text);
    return j;
}

nlohmann::json warning_items_json(const std::vector<Warning>& warnings) {
    nlohmann::json j = nlohmann::json::array();
    for (const Warning& w : warnings) j.push_back(warning_json(w));
    return j;
}

nlohmann::json untangle_json(const UntangleReport& u) {
    return {{"inverted_before", u.inverted_before},
            {"inverted_after", u.inverted_after},
            {"below_target_before", u.below_target_before},
            {"below_target_after", u.below_target_after},
            {"nodes_moved", u.nodes_moved},
            {"max_move", u.max_move},
            {"rounds", u.rounds},
            {"min_quality_after", u.min_quality_after}};
}

nlohmann::json guard_json(const DgHarmonicGuardReport& g) {
    if (!g.checked) return nullptr;
    const auto measure = [](const GuardMeasure& m) {
        return nlohmann::json{
            {"min_quality", m.min_quality}, {"inverted", m.inverted}, {"inverted_on_boundary", m.inverted_on_boundary}};
    };
    return {{"one_pass", measure(g.one_pass)},
            {"bar", g.bar},
            {"measure_seconds", g.measure_seconds},
            {"redone", g.redone},
            {"boundary_folds", g.boundary_folds},
            {"redo", g.redone && g.redo_error.empty() ? measure(g.redo) : nlohmann::json(nullptr)},
            {"redo_error", g.redo_error.empty() ? nlohmann::json(nullptr) : nlohmann::json(g.redo_error)},
            {"increments", g.redone ? nlohmann::json(g.increments) : nlohmann::json(nullptr)},
            {"kept_redo", g.kept_redo},
            {"redo_seconds", g.redo_seconds}};
}

nlohmann::json frame_report_json(const FrameReport& f) {
    return {{"quality", quality_json(f.quality)},
            {"ratio", ratio_json(f.ratio)},
            {"inverted_by_motion", f.inverted_by_motion},
            {"worst_inverted_cells", f.worst_inverted},
            {"inverted_on_boundary", f.inverted_on_boundary},
            {"substeps", f.step.substeps},
            {"invalid_graph_simplices", f.step.invalid_graph_simplices},
            {"rbf_centres", f.step.rbf_centres},
            {"rbf_boundary_error", f.step.rbf_boundary_error},
            {"untangle", f.untangled ? untangle_json(*f.untangled) : nlohmann::json(nullptr)},
            {"last_resort", f.last_resort},
            {"guard", guard_json(f.step.guard)},
            {"seconds", {{"deform", f.step_seconds}, {"untangle", f.repair_seconds}, {"quality", f.quality_seconds}}},
            {"warnings", warning_texts_json(f.warnings)},
            {"warning_items", warning_items_json(f.warnings)}};
}

nlohmann::json options_json(const MethodOptions& o, bool weights_known) {
    nlohmann::json j = nlohmann::json::object();
    for (const MethodOption& row : method_option_table) {
        if (row.tuning) continue;
        const std::string key(row.report_key);
        const OptionValue v = row.get(o);
        switch (row.kind) {
            case OptionKind::number: j[key] = v.number; break;
            case OptionKind::whole_number: j[key] = static_cast<std::int64_t>(v.number); break;
            case OptionKind::number_or_auto: j[key] = v.automatic ? nlohmann::json("auto") : nlohmann::json(v.number); break;
            case OptionKind::word: j[key] = std::string(v.word); break;
            case OptionKind::on_off: j[key] = v.number != 0; break;
        }
    }
    if (!weights_known) j["dg_idw_weights"] = nullptr;
    return j;
}

}  // namespace dgwarp
