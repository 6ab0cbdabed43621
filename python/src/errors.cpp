#include "errors.hpp"

#include <cerrno>
#include <cstring>
#include <tuple>
#include <utility>
#include <vector>

#include "dgwarp/core/error.hpp"

namespace py = pybind11;

namespace dgwarp::python {

namespace {

// The classes, created once at import and kept for the life of the interpreter.
struct Classes {
    PyObject* error = nullptr;
    PyObject* io = nullptr;
    // IoError subclasses that are also the built-in OSError subclass of their
    // errno, as OSError(errno, ...) itself would be: FileNotFoundError, ...
    std::vector<std::pair<int, PyObject*>> io_by_errno;
    PyObject* parse = nullptr;
    PyObject* mesh = nullptr;
    PyObject* format = nullptr;
    PyObject* invalid_result = nullptr;
    PyObject* input = nullptr;
    PyObject* warning = nullptr;
};
Classes classes;

PyObject* new_class(py::module_& m, const char* name, const char* doc, py::tuple bases) {
    const std::string qualified = std::string("dgwarp.") + name;
    // str(e) is the library's message, also for OSError, which would print
    // "[Errno None] None: 'file'" once its filename is set.
    py::dict attributes;
    attributes["__str__"] = py::module_::import("builtins").attr("BaseException").attr("__str__");
    PyObject* c = PyErr_NewExceptionWithDoc(qualified.c_str(), doc, bases.ptr(), attributes.ptr());
    if (!c) throw py::error_already_set();
    m.add_object(name, py::handle(c));  // the module holds a reference; ours is never released
    return c;
}

// Raises an instance of `cls` with `message` and the attributes `attrs`.
void raise(PyObject* cls, const std::string& message, const py::dict& attrs) {
    py::object e = py::reinterpret_borrow<py::object>(cls)(message);
    for (auto item : attrs) py::setattr(e, item.first, item.second);
    PyErr_SetObject(cls, e.ptr());
}

}  // namespace

void bind_errors(py::module_& m) {
    const py::handle builtin_value_error(PyExc_ValueError), builtin_os_error(PyExc_OSError);
    classes.error = new_class(m, "Error", "Base of every error dgwarp's library raises (its message says what and where).",
                              py::make_tuple(py::handle(PyExc_Exception)));
    const py::handle error(classes.error);
    classes.io = new_class(m, "IoError", "A file could not be opened, read or written; `filename` names it.",
                           py::make_tuple(error, builtin_os_error));
    const std::tuple<int, const char*, PyObject*> by_errno[] = {
        {ENOENT, "FileNotFoundIoError", PyExc_FileNotFoundError},
        {EACCES, "PermissionIoError", PyExc_PermissionError},
        {EPERM, "", PyExc_PermissionError},  // the class made for EACCES
        {EISDIR, "IsADirectoryIoError", PyExc_IsADirectoryError},
        {ENOTDIR, "NotADirectoryIoError", PyExc_NotADirectoryError},
    };
    for (const auto& [number, name, builtin] : by_errno) {
        PyObject* c = *name ? new_class(m, name,
                                        "An IoError that is also the built-in OSError subclass of its errno "
                                        "(`except FileNotFoundError` catches a missing file).",
                                        py::make_tuple(py::handle(classes.io), py::handle(builtin)))
                            : classes.io_by_errno.back().second;
        classes.io_by_errno.emplace_back(number, c);
    }
    classes.parse = new_class(m, "ParseError",
                              "A file's content is malformed: `file`, `line` (1-based; 0 when unknown), `expected`, "
                              "`found`.",
                              py::make_tuple(error, builtin_value_error));
    classes.mesh = new_class(m, "MeshError",
                             "Inconsistent data (unknown marker, node id out of range, a plan for another mesh): "
                             "`marker` ('' when none) and `index` (the node or element at fault, -1 when none).",
                             py::make_tuple(error, builtin_value_error));
    classes.format = new_class(m, "FormatError", "A file format is not supported (extension, variant).",
                               py::make_tuple(error, builtin_value_error));
    classes.invalid_result = new_class(m, "InvalidResultError",
                                       "A computed result is invalid (a method's moved graph folds): `count` is how "
                                       "many items are bad.",
                                       py::make_tuple(error, builtin_value_error));
    classes.input = new_class(m, "InputError", "A bad option value (out of range, not finite) or other bad input.",
                              py::make_tuple(error, builtin_value_error));
    {
        const std::string qualified = "dgwarp.DgwarpWarning";
        classes.warning = PyErr_NewExceptionWithDoc(
            qualified.c_str(),
            "Suspicious input that still works (a motion larger than the mesh, nodes outside the graph's hull, ...): "
            "the texts the CLI prints as warnings.",
            PyExc_UserWarning, nullptr);
        if (!classes.warning) throw py::error_already_set();
        m.add_object("DgwarpWarning", py::handle(classes.warning));
    }

    py::register_exception_translator([](std::exception_ptr p) {
        try {
            if (p) std::rethrow_exception(p);
        } catch (const IoError& e) {
            py::dict a;
            a["filename"] = e.file();
            PyObject* cls = classes.io;
            if (const int number = e.error_number(); number != 0) {
                a["errno"] = number;
                a["strerror"] = std::strerror(number);
                for (const auto& [n, c] : classes.io_by_errno)
                    if (n == number) cls = c;
            }
            raise(cls, e.what(), a);
        } catch (const ParseError& e) {
            py::dict a;
            a["file"] = e.file();
            a["line"] = e.line();
            a["expected"] = e.expected();
            a["found"] = e.found();
            raise(classes.parse, e.what(), a);
        } catch (const MeshError& e) {
            py::dict a;
            a["marker"] = e.marker();
            a["index"] = e.index();
            raise(classes.mesh, e.what(), a);
        } catch (const FormatError& e) {
            raise(classes.format, e.what(), py::dict());
        } catch (const InvalidResultError& e) {
            py::dict a;
            a["count"] = e.count();
            raise(classes.invalid_result, e.what(), a);
        } catch (const Error& e) {
            raise(classes.input, e.what(), py::dict());
        }
    });
}

void warn(const std::string& message) {
    if (PyErr_WarnEx(classes.warning, message.c_str(), 1) != 0) throw py::error_already_set();
}

void warn_all(const std::vector<Warning>& warnings) {
    for (const Warning& w : warnings) warn(w.text);
}

}  // namespace dgwarp::python
