#include "py_motion.hpp"

#include <pybind11/numpy.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <cmath>
#include <filesystem>
#include <utility>

#include "bindings.hpp"
#include "dgwarp/core/error.hpp"
#include "dgwarp/io/motion_file.hpp"

namespace py = pybind11;

namespace dgwarp::python {

namespace {

// json.dumps's `default`: NumPy arrays and scalars as lists and numbers.
py::object json_default(py::handle obj) {
    if (py::hasattr(obj, "tolist")) return obj.attr("tolist")();
    throw py::type_error("motion: a value of type " + py::str(py::type::of(obj)).cast<std::string>() +
                         " cannot be written as JSON (numbers, strings, lists, dicts and NumPy arrays can)");
}

/// The place (as motion-file errors name it: "markers.airfoil.translate[0]")
/// and the text of the first NaN or infinity in a motion dict, or "" when
/// there is none: JSON cannot hold them, and json.dumps would refuse them
/// without saying where. Stops at depth 64 (a motion is never that deep; a dict
/// holding itself is then json.dumps's to refuse).
std::pair<std::string, std::string> first_non_finite(py::handle obj, const std::string& at, int depth = 0) {
    if (depth > 64) return {};
    const auto place = [&](const std::string& sub) { return at.empty() ? sub : at + "." + sub; };
    if (py::isinstance<py::dict>(obj)) {
        for (auto item : py::reinterpret_borrow<py::dict>(obj)) {
            auto found = first_non_finite(item.second, place(py::str(item.first).cast<std::string>()), depth + 1);
            if (!found.first.empty()) return found;
        }
    } else if (py::isinstance<py::array>(obj)) {
        return first_non_finite(obj.attr("tolist")(), at, depth + 1);
    } else if (py::isinstance<py::list>(obj) || py::isinstance<py::tuple>(obj)) {
        std::size_t i = 0;
        for (auto item : obj) {
            auto found = first_non_finite(item, at + "[" + std::to_string(i++) + "]", depth + 1);
            if (!found.first.empty()) return found;
        }
    } else if (py::isinstance<py::float_>(obj) || (py::hasattr(obj, "dtype") && py::hasattr(obj, "item"))) {
        const py::object value = py::isinstance<py::float_>(obj) ? py::reinterpret_borrow<py::object>(obj)
                                                                  : obj.attr("item")();
        if (py::isinstance<py::float_>(value) && !std::isfinite(value.cast<double>()))
            return {at.empty() ? "the top level" : at, py::str(value).cast<std::string>()};
    }
    return {};
}

bool is_path(py::handle obj) {
    return py::isinstance<py::str>(obj) || py::hasattr(obj, "__fspath__");
}

}  // namespace

bool is_motion_like(py::handle obj) {
    return py::isinstance<PyMotion>(obj) || py::isinstance<py::dict>(obj) || is_path(obj);
}

MotionPtr motion_arg(py::handle obj) {
    if (py::isinstance<PyMotion>(obj)) return obj.cast<MotionPtr>();
    auto motion = std::make_shared<PyMotion>();
    if (py::isinstance<py::dict>(obj)) {
        if (const auto [at, value] = first_non_finite(obj, ""); !at.empty())
            throw ParseError("motion", 0, "a finite number at " + at, value);
        const std::string text = py::module_::import("json")
                                     .attr("dumps")(obj, py::arg("default") = py::cpp_function(json_default),
                                                    py::arg("allow_nan") = false)
                                     .cast<std::string>();
        motion->spec = parse_motion_file(text, "motion", std::filesystem::current_path());
    } else if (is_path(obj)) {
        const auto path = obj.cast<std::filesystem::path>();
        py::gil_scoped_release release;
        motion->spec = read_motion_file(path);
    } else {
        throw py::type_error("a motion must be a dict in the motion-file form (docs/MOTION.md), the path of a motion "
                             "file, or a dgwarp.Motion; got " +
                             py::str(py::type::of(obj)).cast<std::string>());
    }
    return motion;
}

void bind_motion(py::module_& m) {
    py::class_<PyMotion, std::shared_ptr<PyMotion>>(
        m, "Motion",
        "A motion: how each boundary marker moves, in one frame or a time series (docs/MOTION.md).\n\n"
        "Motion(source): source is a dict in the motion-file form, e.g.\n"
        "  {'markers': {'airfoil': {'rotate': {'angle_deg': 5, 'center': [0.25, 0]}}}},\n"
        "or the path of a motion file. Parse once and pass the Motion to Plan.deform for\n"
        "every frame of a series.")
        .def(py::init([](py::handle source) { return std::const_pointer_cast<PyMotion>(motion_arg(source)); }),
             py::arg("source"))
        .def_property_readonly("frames", [](const PyMotion& p) { return frame_count(p.spec); },
                               "How many frames it describes (the time steps of a periodic motion).")
        .def("__len__", [](const PyMotion& p) { return frame_count(p.spec); })
        .def(
            "time",
            [](const PyMotion& p, std::size_t frame) {
                if (frame >= frame_count(p.spec))
                    throw py::index_error("frame " + std::to_string(frame) + " of a motion with " +
                                          std::to_string(frame_count(p.spec)) + " frames");
                return frame_time(p.spec, frame);
            },
            py::arg("frame"), "The time of a frame (k * time_step for periodic motions, else 0).")
        .def_property_readonly(
            "markers",
            [](const PyMotion& p) {
                std::vector<std::string> names;
                for (const MotionFrame& f : p.spec.frames)
                    for (const auto& entry : f.markers)
                        if (!std::holds_alternative<FixedMotion>(entry.second) &&
                            std::find(names.begin(), names.end(), entry.first) == names.end())
                            names.push_back(entry.first);
                return names;
            },
            "The markers some frame moves (sorted by name within each frame).")
        .def_property_readonly(
            "shared_nodes",
            [](const PyMotion& p) {
                return std::string(p.spec.shared_nodes == SharedNodeRule::moving_wins ? "moving_wins" : "static_wins");
            },
            "What nodes on several markers do: 'moving_wins' or 'static_wins'.")
        .def_property_readonly("source", [](const PyMotion& p) { return p.spec.source; },
                               "The motion file, or 'motion' for a dict.")
        .def("__repr__", [](const PyMotion& p) {
            return "dgwarp.Motion('" + p.spec.source + "', " + std::to_string(frame_count(p.spec)) + " frame" +
                   (frame_count(p.spec) == 1 ? "" : "s") + ")";
        });
}

}  // namespace dgwarp::python
