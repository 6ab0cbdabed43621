#include "py_options.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <string_view>

#include "dgwarp/core/error.hpp"
#include "dgwarp/methods/option_table.hpp"

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
    for (const MethodOption& o : method_option_table)
        if (!o.tuning) s += (s.empty() ? "" : ", ") + keyword(o.name);
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
/// CLI refuses it (deform_setup.cpp). Each value goes through the option
/// table's text (methods/option_table.hpp), which checks its range.
MethodOptions method_options(Method method, const py::kwargs& kwargs, const char* function) {
    MethodOptions o;
    for (auto item : kwargs) {
        const std::string name = py::str(item.first);
        const py::handle value = item.second;
        const MethodOption* row = find_method_option(name);
        if (!row || row->tuning || name.find('-') != std::string::npos)
            throw py::type_error(std::string(function) + "() got an unexpected keyword argument '" + name +
                                 "'; the method options are " + option_keywords());
        if (row->method != method)
            throw py::value_error(name + " is an option of " + std::string(method_name(row->method)) +
                                  "; it does nothing with " + std::string(method_name(method)));
        std::string text;
        switch (row->kind) {
            case OptionKind::on_off:
                if (!py::isinstance<py::bool_>(value)) throw py::type_error(name + " must be True or False");
                text = value.cast<bool>() ? "true" : "false";
                break;
            case OptionKind::word:
                if (!py::isinstance<py::str>(value))
                    throw py::type_error(name + " must be " + expected_values(*row) + ", got " +
                                         py::repr(value).cast<std::string>());
                text = value.cast<std::string>();
                break;
            default:
                if (row->kind == OptionKind::number_or_auto && py::isinstance<py::str>(value)) {
                    text = value.cast<std::string>();
                    if (text != "auto")
                        throw py::value_error(name + " must be " + expected_values(*row) + ", got '" + text + "'");
                    break;
                }
                {
                    // Exact: the shortest text that reads back to the same double.
                    const double v = number_option(value, name);
                    char buf[32];
                    const auto [end, ec] = std::to_chars(buf, buf + sizeof buf, v);
                    text.assign(buf, end);
                }
        }
        try {
            row->set(o, parse_option_value(*row, text));
        } catch (const UsageError& e) {
            // "method option a-translation: ..." in Python's spelling of the name.
            std::string message = e.what();
            if (const std::size_t at = message.find(row->name); at != std::string::npos)
                message.replace(at, row->name.size(), name);
            throw UsageError(message);  // dgwarp.InputError, as the library's range checks
        }
    }
    return o;
}

py::dict options_dict(Method method, const MethodOptions& o) {
    py::dict d;
    for (const MethodOption& row : method_option_table) {
        if (row.method != method || row.tuning) continue;
        const OptionValue v = row.get(o);
        const std::string key = keyword(row.name);
        switch (row.kind) {
            case OptionKind::number: d[key.c_str()] = v.number; break;
            case OptionKind::whole_number: d[key.c_str()] = static_cast<long long>(v.number); break;
            case OptionKind::number_or_auto:
                d[key.c_str()] = v.automatic ? py::object(py::str("auto")) : py::object(py::float_(v.number));
                break;
            case OptionKind::word: d[key.c_str()] = std::string(v.word); break;
            case OptionKind::on_off: d[key.c_str()] = v.number != 0; break;
        }
    }
    return d;
}

}  // namespace dgwarp::python
