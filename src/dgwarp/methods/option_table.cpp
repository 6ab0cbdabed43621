// option_table.hpp: the rows, and text in and out of them.
#include "dgwarp/methods/option_table.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <variant>

#include "dgwarp/core/error.hpp"

namespace dgwarp {

namespace {

OptionValue number_value(double x) { return {x, {}, false}; }
OptionValue word_value(std::string_view w) { return {0, w, false}; }
/// `x`, or "auto" when it is `automatic` (the member's value for it).
OptionValue auto_or(double x, double automatic) { return {x, {}, x == automatic}; }
OptionValue auto_or(const std::optional<double>& x) { return {x.value_or(0), {}, !x}; }

}  // namespace

const std::array<MethodOption, 27> method_option_table = {{
    {"a-translation", Method::dg_idw, OptionKind::number, "a_translation", true, dg_idw_a_min, dg_idw_a_max, false, {},
     "DG-IDW weight a of the translation, the paper's 7",
     [](const MethodOptions& o) { return number_value(o.dg_idw.a_translation); },
     [](MethodOptions& o, const OptionValue& v) { o.dg_idw.a_translation = v.number; }},
    {"a-rotation", Method::dg_idw, OptionKind::number, "a_rotation", true, dg_idw_a_min, dg_idw_a_max, false, {},
     "DG-IDW weight a of the rotation, the paper's 1.4",
     [](const MethodOptions& o) { return number_value(o.dg_idw.a_rotation); },
     [](MethodOptions& o, const OptionValue& v) { o.dg_idw.a_rotation = v.number; }},
    {"length-scale", Method::dg_idw, OptionKind::number_or_auto, "length_scale", true, 0, HUGE_VAL, true, {},
     "DG-IDW reference length L the distances are divided by: a number (1 reproduces the paper) or 'auto' (the "
     "moving boundary's diagonal, reduced so that max(a) L fits in the gap between the moving and the static "
     "boundary; docs/dg-idw-length-scale.md)",
     [](const MethodOptions& o) { return auto_or(o.dg_idw.length_scale, 0); },
     [](MethodOptions& o, const OptionValue& v) { o.dg_idw.length_scale = v.automatic ? 0 : v.number; }},
    {"dg-idw-weights", Method::dg_idw, OptionKind::word, "dg_idw_weights", true, 0, 0, false, {"paper", "continuous"},
     "DG-IDW corner weights: 'paper' (the paper's formula) or 'continuous' (each weight times the node's "
     "barycentric coordinate: no jump across graph faces; docs/dg-idw.md)",
     [](const MethodOptions& o) { return word_value(weighting_name(o.dg_idw.weighting)); },
     [](MethodOptions& o, const OptionValue& v) {
         o.dg_idw.weighting = v.word == "continuous" ? DgIdwWeighting::continuous : DgIdwWeighting::paper;
     }},
    {"dgm-substep", Method::dgm, OptionKind::on_off, "dgm_substep", false, 0, 0, false, {},
     "DGM: when the moved graph is invalid, split the motion into increments (default: fail)",
     [](const MethodOptions& o) {
         return number_value(o.dgm.on_invalid == DgmOptions::OnInvalidGraph::substep ? 1 : 0);
     },
     [](MethodOptions& o, const OptionValue& v) {
         o.dgm.on_invalid = v.number != 0 ? DgmOptions::OnInvalidGraph::substep : DgmOptions::OnInvalidGraph::fail;
     }},
    {"idw-moving-exponent", Method::idw, OptionKind::number, "idw_exponent_moving", false, 0, 16, true, {},
     "IDW: exponent c_d of the moving nodes' distances",
     [](const MethodOptions& o) { return number_value(o.idw.exponent_moving); },
     [](MethodOptions& o, const OptionValue& v) { o.idw.exponent_moving = v.number; }},
    {"idw-static-exponent", Method::idw, OptionKind::number, "idw_exponent_static", false, 0, 16, true, {},
     "IDW: exponent c_s of the static nodes' distances",
     [](const MethodOptions& o) { return number_value(o.idw.exponent_static); },
     [](MethodOptions& o, const OptionValue& v) { o.idw.exponent_static = v.number; }},
    {"rbf-radius", Method::rbf, OptionKind::number, "rbf_radius", true, 0, HUGE_VAL, false, {},
     "RBF: Wendland C2 support radius (0 = global: dense solve)",
     [](const MethodOptions& o) { return number_value(o.rbf.support_radius); },
     [](MethodOptions& o, const OptionValue& v) { o.rbf.support_radius = v.number; }},
    {"rbf-greedy", Method::rbf, OptionKind::number, "rbf_greedy_tolerance", true, 0, HUGE_VAL, false, {},
     "RBF: greedy data reduction to this boundary error (mesh units; 0 = all centres)",
     [](const MethodOptions& o) { return number_value(o.rbf.greedy_tolerance); },
     [](MethodOptions& o, const OptionValue& v) { o.rbf.greedy_tolerance = v.number; }},
    {"harmonic-wall-spacing", Method::dg_harmonic, OptionKind::number, "harmonic_wall_spacing", true, 0, HUGE_VAL,
     true, {},
     "DG-harmonic: coarse-level spacing next to a wall, in boundary-node spacings (smaller: a finer coarse level, "
     "slower steps; docs/dg-harmonic.md)",
     [](const MethodOptions& o) { return number_value(o.dg_harmonic.wall_spacing); },
     [](MethodOptions& o, const OptionValue& v) { o.dg_harmonic.wall_spacing = v.number; }},
    {"harmonic-growth", Method::dg_harmonic, OptionKind::number, "harmonic_growth", true, 0, HUGE_VAL, true, {},
     "DG-harmonic: coarse-level spacing away from the walls, as a fraction of the wall distance",
     [](const MethodOptions& o) { return number_value(o.dg_harmonic.growth); },
     [](MethodOptions& o, const OptionValue& v) { o.dg_harmonic.growth = v.number; }},
    {"harmonic-redo-below", Method::dg_harmonic, OptionKind::number, "harmonic_redo_below", false, -1, 0.99, false, {},
     "DG-harmonic's guard: a step whose minimum quality falls below this fraction of the original mesh's, or that "
     "inverts a cell, is solved again by laplacian and the better result kept (0: only when a cell inverts; -1: "
     "never; docs/dg-harmonic.md)",
     [](const MethodOptions& o) { return number_value(o.dg_harmonic.redo_below); },
     [](MethodOptions& o, const OptionValue& v) { o.dg_harmonic.redo_below = v.number; }},
    {"laplacian-increments", Method::laplacian, OptionKind::whole_number, "laplacian_increments", true, 1, 64, false,
     {}, "laplacian: increments per step, each assembled on the mesh the earlier ones moved (docs/laplacian.md)",
     [](const MethodOptions& o) { return number_value(o.laplacian.increments); },
     [](MethodOptions& o, const OptionValue& v) { o.laplacian.increments = static_cast<int>(v.number); }},
    {"laplacian-exponent", Method::laplacian, OptionKind::number, "laplacian_exponent", true, 0, 4, false, {},
     "laplacian: stiffness exponent e, stiffness (mean volume / cell volume)^e",
     [](const MethodOptions& o) { return number_value(o.laplacian.stiffness_exponent); },
     [](MethodOptions& o, const OptionValue& v) { o.laplacian.stiffness_exponent = v.number; }},
    {"laplacian-model", Method::laplacian, OptionKind::word, "laplacian_model", true, 0, 0, false,
     {"elasticity", "laplacian"},
     "laplacian: 'elasticity' (linear elasticity, the components coupled) or 'laplacian' (the displacement "
     "Laplacian per component)",
     [](const MethodOptions& o) {
         return word_value(o.laplacian.model == LaplacianModel::laplacian ? "laplacian" : "elasticity");
     },
     [](MethodOptions& o, const OptionValue& v) {
         o.laplacian.model = v.word == "laplacian" ? LaplacianModel::laplacian : LaplacianModel::elasticity;
     }},
    // Tuning: the methods' internal constants.
    {"dgm-max-substeps", Method::dgm, OptionKind::whole_number, "dgm_max_substeps", true, 1, 1 << 20, false, {},
     "DGM: the most increments --dgm-substep splits a motion into",
     [](const MethodOptions& o) { return number_value(o.dgm.max_substeps); },
     [](MethodOptions& o, const OptionValue& v) { o.dgm.max_substeps = static_cast<int>(v.number); }, true},
    {"idw-length-scale", Method::idw, OptionKind::number_or_auto, "idw_length_scale", false, 0, HUGE_VAL, true, {},
     "IDW: reference length the distances are divided by ('auto': the boundary's diagonal)",
     [](const MethodOptions& o) { return auto_or(o.idw.length_scale, 0); },
     [](MethodOptions& o, const OptionValue& v) { o.idw.length_scale = v.automatic ? 0 : v.number; }, true},
    {"rbf-max-dense-bytes", Method::rbf, OptionKind::number_or_auto, "rbf_max_dense_bytes", true, 0, 9007199254740992.0,
     true, {}, "RBF: the largest dense system it factorises, in bytes ('auto': its default)",
     [](const MethodOptions& o) { return auto_or(static_cast<double>(o.rbf.max_dense_bytes), 0); },
     [](MethodOptions& o, const OptionValue& v) {
         o.rbf.max_dense_bytes = v.automatic ? 0 : static_cast<std::size_t>(v.number);
     },
     true},
    {"rbf-solver", Method::rbf, OptionKind::word, "rbf_solver", true, 0, 0, false, {"automatic", "dense", "sparse"},
     "RBF: the factorisation ('automatic': dense for a global support, sparse otherwise)",
     [](const MethodOptions& o) {
         return word_value(o.rbf.solver == RbfSolver::dense    ? "dense"
                           : o.rbf.solver == RbfSolver::sparse ? "sparse"
                                                               : "automatic");
     },
     [](MethodOptions& o, const OptionValue& v) {
         o.rbf.solver = v.word == "dense" ? RbfSolver::dense : v.word == "sparse" ? RbfSolver::sparse : RbfSolver::automatic;
     }, true},
    {"harmonic-translation-exponent", Method::dg_harmonic, OptionKind::number_or_auto, "harmonic_translation_exponent",
     true, 0, 4, false, {}, "DG-harmonic: conductivity exponent of the translation ('auto': 3 in 2D, 2.5 in 3D)",
     [](const MethodOptions& o) { return auto_or(o.dg_harmonic.translation_exponent); },
     [](MethodOptions& o, const OptionValue& v) {
         o.dg_harmonic.translation_exponent = v.automatic ? std::nullopt : std::optional<double>(v.number);
     },
     true},
    {"harmonic-rotation-exponent", Method::dg_harmonic, OptionKind::number_or_auto, "harmonic_rotation_exponent", true,
     0, 4, false, {}, "DG-harmonic: conductivity exponent of the rotation ('auto': 0 in 2D, 2.5 in 3D)",
     [](const MethodOptions& o) { return auto_or(o.dg_harmonic.rotation_exponent); },
     [](MethodOptions& o, const OptionValue& v) {
         o.dg_harmonic.rotation_exponent = v.automatic ? std::nullopt : std::optional<double>(v.number);
     },
     true},
    {"harmonic-rigid-zone", Method::dg_harmonic, OptionKind::number_or_auto, "harmonic_rigid_zone", true, 0, HUGE_VAL,
     false, {}, "DG-harmonic: the rotation's rigid zone, a fraction of the moving boundary's diagonal ('auto': 0.25 in 2D, 0 in 3D)",
     [](const MethodOptions& o) { return auto_or(o.dg_harmonic.rigid_zone); },
     [](MethodOptions& o, const OptionValue& v) {
         o.dg_harmonic.rigid_zone = v.automatic ? std::nullopt : std::optional<double>(v.number);
     },
     true},
    {"harmonic-rigid-gap", Method::dg_harmonic, OptionKind::number, "harmonic_rigid_gap", true, 0, HUGE_VAL, false, {},
     "DG-harmonic: the rigid zone's bound, a fraction of the distance to the static boundary",
     [](const MethodOptions& o) { return number_value(o.dg_harmonic.rigid_gap); },
     [](MethodOptions& o, const OptionValue& v) { o.dg_harmonic.rigid_gap = v.number; }, true},
    {"harmonic-redo-max-increments", Method::dg_harmonic, OptionKind::whole_number, "harmonic_redo_max_increments",
     false, 1, 64, false, {}, "DG-harmonic's guard: the most increments laplacian's solve again may use",
     [](const MethodOptions& o) { return number_value(o.dg_harmonic.redo_max_increments); },
     [](MethodOptions& o, const OptionValue& v) { o.dg_harmonic.redo_max_increments = static_cast<int>(v.number); }, true},
    {"harmonic-redo-max-nodes-3d", Method::dg_harmonic, OptionKind::whole_number, "harmonic_redo_max_nodes_3d", false,
     0, 9007199254740992.0, false, {}, "DG-harmonic's guard: the largest 3D mesh laplacian solves again, in nodes",
     [](const MethodOptions& o) { return number_value(static_cast<double>(o.dg_harmonic.redo_max_nodes_3d)); },
     [](MethodOptions& o, const OptionValue& v) {
         o.dg_harmonic.redo_max_nodes_3d = static_cast<std::int64_t>(v.number);
     }, true},
    {"laplacian-max-increments", Method::laplacian, OptionKind::whole_number, "laplacian_max_increments", true, 1, 64,
     false, {}, "laplacian: the most increments it doubles to while a simplex folds",
     [](const MethodOptions& o) { return number_value(o.laplacian.max_increments); },
     [](MethodOptions& o, const OptionValue& v) { o.laplacian.max_increments = static_cast<int>(v.number); }, true},
    {"laplacian-poisson-ratio", Method::laplacian, OptionKind::number, "laplacian_poisson_ratio", true, 0, 0.45, false,
     {}, "laplacian: Poisson's ratio of the elasticity model",
     [](const MethodOptions& o) { return number_value(o.laplacian.poisson_ratio); },
     [](MethodOptions& o, const OptionValue& v) { o.laplacian.poisson_ratio = v.number; }, true},
}};

const MethodOption* find_method_option(std::string_view name) {
    if (name.starts_with("--")) name.remove_prefix(2);
    for (const MethodOption& option : method_option_table)
        if (option.name.size() == name.size() &&
            std::equal(name.begin(), name.end(), option.name.begin(),
                       [](char a, char b) { return a == b || (a == '_' && b == '-'); }))
            return &option;
    return nullptr;
}

std::optional<Method> option_method(std::string_view name) {
    const MethodOption* option = find_method_option(name);
    return option ? std::optional<Method>(option->method) : std::nullopt;
}

namespace {

/// A bound for a message: "16", "0.99", "1e+06".
std::string bound_text(double x) {
    char text[32];
    std::snprintf(text, sizeof text, "%g", x);
    return text;
}

/// Shortest text that reads back to exactly `x`.
std::string exact_text(double x) {
    char text[32];
    const auto [end, ec] = std::to_chars(text, text + sizeof text, x);
    return std::string(text, end);
}

std::string option_list() {
    std::string s;
    for (const MethodOption& o : method_option_table) s += (s.empty() ? "" : ", ") + std::string(o.name);
    return s;
}

}  // namespace

std::string expected_values(const MethodOption& o) {
    const auto range = [&] {
        if (std::isinf(o.high)) return o.low_open ? "a positive number" : "a number >= " + bound_text(o.low);
        if (o.low_open) return "a number > " + bound_text(o.low) + " and <= " + bound_text(o.high);
        return "a number from " + bound_text(o.low) + " to " + bound_text(o.high);
    };
    switch (o.kind) {
        case OptionKind::number: return range();
        case OptionKind::whole_number:
            return "a whole number from " + bound_text(o.low) + " to " + bound_text(o.high);
        case OptionKind::number_or_auto: return range() + " or 'auto'";
        case OptionKind::word: {
            std::string s;
            std::size_t n = 0;
            for (std::string_view w : o.words) n += !w.empty();
            for (std::size_t i = 0; i < n; ++i) {
                s.append(i == 0 ? "" : i + 1 == n ? " or " : ", ");
                s.append(1, '\'').append(o.words[i]).append(1, '\'');
            }
            return s;
        }
        case OptionKind::on_off: return "true or false (on/off, yes/no, 1/0)";
    }
    return {};
}

OptionValue parse_option_value(const MethodOption& o, std::string_view text, bool check_range) {
    const auto refuse = [&]() -> OptionValue {
        throw UsageError("method option " + std::string(o.name) + ": expected " + expected_values(o) + ", got '" +
                         std::string(text) + "'");
    };
    // A number (any, unless the range is checked: then finite and in it).
    const auto number = [&](double& v) {
        // As a command line's number: an explicit '+' too (from_chars takes only '-').
        std::string_view digits = text;
        if (digits.size() > 1 && digits[0] == '+' && digits[1] != '-' && digits[1] != '+') digits.remove_prefix(1);
        const char* end = digits.data() + digits.size();
        const auto [ptr, ec] = std::from_chars(digits.data(), end, v);
        if (digits.empty() || ec != std::errc() || ptr != end) return false;
        return !check_range || (std::isfinite(v) && v >= o.low && v <= o.high && !(o.low_open && v == o.low));
    };
    double v = 0;
    switch (o.kind) {
        case OptionKind::number:
            if (!number(v)) return refuse();
            return {v, {}};
        case OptionKind::whole_number:  // the member is an integer: never NaN, never beyond 2^53 here
            if (!number(v) || !(std::abs(v) <= 9007199254740992.0) || v != std::floor(v)) return refuse();
            return {v, {}};
        case OptionKind::number_or_auto:
            if (text == "auto") return {0, {}, true};
            if (!number(v)) return refuse();
            return {v, {}};
        case OptionKind::word:
            for (std::string_view w : o.words)
                if (!w.empty() && text == w) return {0, w};
            return refuse();
        case OptionKind::on_off:
            if (text == "true" || text == "on" || text == "yes" || text == "1") return {1, {}};
            if (text == "false" || text == "off" || text == "no" || text == "0") return {0, {}};
            return refuse();
    }
    return refuse();
}

std::string option_text(const MethodOption& o, const MethodOptions& options) {
    const OptionValue v = o.get(options);
    switch (o.kind) {
        case OptionKind::word: return std::string(v.word);
        case OptionKind::on_off: return v.number != 0 ? "true" : "false";
        case OptionKind::number_or_auto:
            if (v.automatic) return "auto";
            return exact_text(v.number);
        default: return exact_text(v.number);
    }
}

void set_method_option(MethodOptions& options, std::string_view name, std::string_view text) {
    const MethodOption* o = find_method_option(name);
    if (!o) throw UsageError("unknown method option '" + std::string(name) + "'; the method options are " + option_list());
    o->set(options, parse_option_value(*o, text));
}

std::string method_options_text(const MethodOptions& options) {
    std::string text;
    for (const MethodOption& o : method_option_table)
        text += std::string(o.name) + " " + option_text(o, options) + "\n";
    return text;
}

MethodOptions method_options_from_text(std::string_view text) {
    MethodOptions options;
    while (!text.empty()) {
        const std::size_t end = std::min(text.find('\n'), text.size());
        const std::string_view line = text.substr(0, end);
        text.remove_prefix(std::min(end + 1, text.size()));
        if (line.empty()) continue;
        const std::size_t space = line.find(' ');
        if (space == std::string_view::npos)
            throw UsageError("method options: expected 'name value', got '" + std::string(line) + "'");
        const std::string_view name = line.substr(0, space);
        const MethodOption* o = find_method_option(name);
        if (!o)
            throw UsageError("unknown method option '" + std::string(name) + "'; the method options are " + option_list());
        o->set(options, parse_option_value(*o, line.substr(space + 1), false));
    }
    return options;
}

MethodOptions options_with_plan(const Plan& plan, const MethodOptions& run) {
    MethodOptions planned = run;  // the plan's method's options, as the plan holds them
    if (const auto* d = std::get_if<DgIdwPlan>(&plan)) planned.dg_idw = d->options;
    if (const auto* h = std::get_if<DgHarmonicPlan>(&plan)) planned.dg_harmonic = h->options;
    const Method method = plan_method(plan);
    MethodOptions used = run;
    for (const MethodOption& o : method_option_table)
        if (o.method == method && o.kept_by_plan) o.set(used, o.get(planned));
    return used;
}

}  // namespace dgwarp
