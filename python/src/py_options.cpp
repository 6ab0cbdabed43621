#include "py_options.hpp"

#include <algorithm>
#include <cmath>
#include <string_view>

#include "dgwarp/methods/option_names.hpp"

namespace py = pybind11;

namespace dgwarp::python {

namespace {

std::string method_list() {
    std::string s;
    for (Method m : all_methods) s += (s.empty() ? "" : ", ") + std::string(method_name(m));
    return s;
}

std::string keyword(std::string_view option) {
    std::string k(option);
    std::replace(k.begin(), k.end(), '-', '_');
    return k;
}

std::string option_keywords() {
    std::string s;
    for (const MethodOptionName& o : method_option_names) s += (s.empty() ? "" : ", ") + keyword(o.name);
    return s;
}

double number_option(py::handle value, const std::string& name) {
    if (py::isinstance<py::bool_>(value) || !(py::isinstance<py::float_>(value) || py::isinstance<py::int_>(value) ||
                                              py::hasattr(value, "__float__")))
        throw py::type_error(name + " must be a number, got " + py::str(py::type::of(value)).cast<std::string>());
    double v = 0;
    try {
        // float(value): refuses arrays of more than one value
        v = py::float_(py::reinterpret_borrow<py::object>(value)).cast<double>();
    } catch (py::error_already_set& e) {
        if (e.matches(PyExc_KeyboardInterrupt) || e.matches(PyExc_MemoryError)) throw;
        throw py::type_error(name + " must be a number, got " + py::repr(value).cast<std::string>() + " (" +
                             e.what() + ")");
    }
    if (!std::isfinite(v)) throw py::value_error(name + " must be finite, got " + py::repr(value).cast<std::string>());
    return v;
}

}  // namespace

Method method_arg(const std::string& name) {
    std::string dashed = name;
    std::replace(dashed.begin(), dashed.end(), '_', '-');
    if (auto m = method_from_name(dashed)) return *m;
    throw py::value_error("unknown method '" + name + "'; choose one of " + method_list());
}

SharedNodeRule shared_nodes_arg(const std::string& rule) {
    if (rule == "moving_wins") return SharedNodeRule::moving_wins;
    if (rule == "static_wins") return SharedNodeRule::static_wins;
    throw py::value_error("shared_nodes must be 'moving_wins' or 'static_wins', got '" + rule + "'");
}

double shared_tolerance_arg(double tolerance) {
    // As a motion file's shared_tolerance (a length > 0), with 0 for its default.
    if (!(std::isfinite(tolerance) && tolerance >= 0))
        throw py::value_error("shared_tolerance must be a length > 0 (or 0: 1e-9 x the mesh's diagonal), got " +
                              py::repr(py::float_(tolerance)).cast<std::string>());
    return tolerance;
}

const char* shared_nodes_name(SharedNodeRule rule) {
    return rule == SharedNodeRule::moving_wins ? "moving_wins" : "static_wins";
}

/// The method options given as keyword arguments (as the CLI's flags, with
/// '_' for '-'); an option of another method than `method` is refused, as the
/// CLI refuses it (deform_setup.cpp). Ranges are checked by the library.
MethodOptions method_options(Method method, const py::kwargs& kwargs, const char* function) {
    MethodOptions o;
    for (auto item : kwargs) {
        const std::string name = py::str(item.first);
        const py::handle value = item.second;
        const std::optional<Method> owner = option_method(name);
        if (!owner || name.find('-') != std::string::npos)
            throw py::type_error(std::string(function) + "() got an unexpected keyword argument '" + name +
                                 "'; the method options are " + option_keywords());
        if (*owner != method)
            throw py::value_error(name + " is an option of " + std::string(method_name(*owner)) +
                                  "; it does nothing with " + std::string(method_name(method)));
        if (name == "a_translation") o.dg_idw.a_translation = number_option(value, name);
        else if (name == "a_rotation") o.dg_idw.a_rotation = number_option(value, name);
        else if (name == "length_scale") {
            if (py::isinstance<py::str>(value)) {
                if (value.cast<std::string>() != "auto")
                    throw py::value_error("length_scale must be a positive number or 'auto', got '" +
                                          value.cast<std::string>() + "'");
                o.dg_idw.length_scale = 0;  // auto
            } else {
                o.dg_idw.length_scale = number_option(value, name);
                if (!(o.dg_idw.length_scale > 0))
                    throw py::value_error("length_scale must be a positive number or 'auto', got " +
                                          py::repr(value).cast<std::string>());
            }
        } else if (name == "dg_idw_weights") {
            const std::string w = py::str(value);
            if (w != "paper" && w != "continuous")
                throw py::value_error("dg_idw_weights must be 'paper' or 'continuous', got '" + w + "'");
            o.dg_idw.weighting = w == "continuous" ? DgIdwWeighting::continuous : DgIdwWeighting::paper;
        } else if (name == "dgm_substep") {
            if (!py::isinstance<py::bool_>(value)) throw py::type_error("dgm_substep must be True or False");
            o.dgm.on_invalid = value.cast<bool>() ? DgmOptions::OnInvalidGraph::substep : DgmOptions::OnInvalidGraph::fail;
        } else if (name == "idw_moving_exponent") o.idw.exponent_moving = number_option(value, name);
        else if (name == "idw_static_exponent") o.idw.exponent_static = number_option(value, name);
        else if (name == "rbf_radius") o.rbf.support_radius = number_option(value, name);
        else if (name == "rbf_greedy") o.rbf.greedy_tolerance = number_option(value, name);
        else if (name == "harmonic_wall_spacing") o.dg_harmonic.wall_spacing = number_option(value, name);
        else if (name == "harmonic_growth") o.dg_harmonic.growth = number_option(value, name);
        else if (name == "harmonic_redo_below") o.dg_harmonic.redo_below = number_option(value, name);
        else if (name == "laplacian_increments") {
            const double n = number_option(value, name);
            if (!(n >= 1 && n <= 64 && n == std::floor(n)))
                throw py::value_error("laplacian_increments must be a whole number from 1 to 64, got " +
                                      py::repr(value).cast<std::string>());
            o.laplacian.increments = static_cast<int>(n);
        } else if (name == "laplacian_exponent") o.laplacian.stiffness_exponent = number_option(value, name);
        else if (name == "laplacian_model") {
            const std::string m = py::str(value);
            if (m != "elasticity" && m != "laplacian")
                throw py::value_error("laplacian_model must be 'elasticity' or 'laplacian', got '" + m + "'");
            o.laplacian.model = m == "laplacian" ? LaplacianModel::laplacian : LaplacianModel::elasticity;
        }
        else throw std::logic_error("method option " + name + " is not bound");
    }
    return o;
}

py::dict options_dict(Method method, const MethodOptions& o) {
    py::dict d;
    switch (method) {
        case Method::dg_idw:
            d["a_translation"] = o.dg_idw.a_translation;
            d["a_rotation"] = o.dg_idw.a_rotation;
            d["length_scale"] = o.dg_idw.length_scale == 0 ? py::object(py::str("auto")) : py::object(py::float_(o.dg_idw.length_scale));
            d["dg_idw_weights"] = weighting_name(o.dg_idw.weighting);
            break;
        case Method::dgm: d["dgm_substep"] = o.dgm.on_invalid == DgmOptions::OnInvalidGraph::substep; break;
        case Method::idw:
            d["idw_moving_exponent"] = o.idw.exponent_moving;
            d["idw_static_exponent"] = o.idw.exponent_static;
            break;
        case Method::rbf:
            d["rbf_radius"] = o.rbf.support_radius;
            d["rbf_greedy"] = o.rbf.greedy_tolerance;
            break;
        case Method::dg_harmonic:
            d["harmonic_wall_spacing"] = o.dg_harmonic.wall_spacing;
            d["harmonic_growth"] = o.dg_harmonic.growth;
            d["harmonic_redo_below"] = o.dg_harmonic.redo_below;
            break;
        case Method::laplacian:
            d["laplacian_increments"] = o.laplacian.increments;
            d["laplacian_exponent"] = o.laplacian.stiffness_exponent;
            d["laplacian_model"] = o.laplacian.model == LaplacianModel::laplacian ? "laplacian" : "elasticity";
            break;
    }
    return d;
}

}  // namespace dgwarp::python
