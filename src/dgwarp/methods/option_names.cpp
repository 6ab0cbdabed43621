#include "dgwarp/methods/option_names.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <string>

#include "dgwarp/core/error.hpp"

namespace dgwarp {

std::optional<Method> option_method(std::string_view name) {
    if (name.starts_with("--")) name.remove_prefix(2);
    for (const MethodOptionName& option : method_option_names)
        if (option.name.size() == name.size() &&
            std::equal(name.begin(), name.end(), option.name.begin(),
                       [](char a, char b) { return a == b || (a == '_' && b == '-'); }))
            return option.method;
    return std::nullopt;
}

namespace {

std::string option_list() {
    std::string s;
    for (const MethodOptionName& o : method_option_names) s += (s.empty() ? "" : ", ") + std::string(o.name);
    return s;
}

[[noreturn]] void bad_value(std::string_view name, std::string_view value, const std::string& expected) {
    throw Error("method option " + std::string(name) + ": expected " + expected + ", got '" + std::string(value) + "'");
}

double number(std::string_view name, std::string_view value) {
    double v = 0;
    const char* end = value.data() + value.size();
    const auto [ptr, ec] = std::from_chars(value.data(), end, v);
    if (value.empty() || ec != std::errc() || ptr != end || !std::isfinite(v)) bad_value(name, value, "a finite number");
    return v;
}

}  // namespace

void set_method_option(MethodOptions& o, std::string_view name, std::string_view value) {
    if (!option_method(name))
        throw Error("unknown method option '" + std::string(name) + "'; the method options are " + option_list());
    if (name.starts_with("--")) name.remove_prefix(2);
    std::string n(name);
    std::replace(n.begin(), n.end(), '_', '-');
    if (n == "a-translation") o.dg_idw.a_translation = number(name, value);
    else if (n == "a-rotation") o.dg_idw.a_rotation = number(name, value);
    else if (n == "length-scale") {
        if (value == "auto") o.dg_idw.length_scale = 0;
        else {
            o.dg_idw.length_scale = number(name, value);
            if (!(o.dg_idw.length_scale > 0)) bad_value(name, value, "a positive number or 'auto'");
        }
    } else if (n == "dg-idw-weights") {
        if (value != "paper" && value != "continuous") bad_value(name, value, "'paper' or 'continuous'");
        o.dg_idw.weighting = value == "continuous" ? DgIdwWeighting::continuous : DgIdwWeighting::paper;
    } else if (n == "dgm-substep") {
        const bool on = value == "true" || value == "on" || value == "yes" || value == "1";
        if (!on && value != "false" && value != "off" && value != "no" && value != "0")
            bad_value(name, value, "true or false (on/off, yes/no, 1/0)");
        o.dgm.on_invalid = on ? DgmOptions::OnInvalidGraph::substep : DgmOptions::OnInvalidGraph::fail;
    } else if (n == "idw-moving-exponent") o.idw.exponent_moving = number(name, value);
    else if (n == "idw-static-exponent") o.idw.exponent_static = number(name, value);
    else if (n == "rbf-radius") o.rbf.support_radius = number(name, value);
    else if (n == "rbf-greedy") o.rbf.greedy_tolerance = number(name, value);
    else if (n == "harmonic-wall-spacing") o.dg_harmonic.wall_spacing = number(name, value);
    else if (n == "harmonic-growth") o.dg_harmonic.growth = number(name, value);
    else if (n == "harmonic-redo-below") o.dg_harmonic.redo_below = number(name, value);
    else if (n == "laplacian-increments") {
        const double v = number(name, value);
        if (!(v >= 1 && v <= 64 && v == std::floor(v))) bad_value(name, value, "a whole number from 1 to 64");
        o.laplacian.increments = static_cast<int>(v);
    } else if (n == "laplacian-exponent") o.laplacian.stiffness_exponent = number(name, value);
    else if (n == "laplacian-model") {
        if (value != "elasticity" && value != "laplacian") bad_value(name, value, "'elasticity' or 'laplacian'");
        o.laplacian.model = value == "laplacian" ? LaplacianModel::laplacian : LaplacianModel::elasticity;
    } else throw std::logic_error("method option " + n + " has no text form");
}

}  // namespace dgwarp
