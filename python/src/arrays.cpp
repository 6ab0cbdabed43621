#include "arrays.hpp"

#include <cmath>
#include <limits>
#include <string>

namespace py = pybind11;

namespace dgwarp::python {

namespace {

std::string dims_text(py::ssize_t rows, py::ssize_t cols, py::ssize_t cols_alt) {
    const std::string r = rows == any_rows ? "n" : std::to_string(rows);
    if (cols == any_rows) return "(" + r + ",)";
    std::string c = std::to_string(cols);
    if (cols_alt > 0) c += " or " + std::to_string(cols_alt);
    return "(" + r + ", " + c + ")";
}

// `obj` as an ndarray: itself when it is one (checked, not converted), else
// np.asarray(obj, dtype) (a list or tuple; TypeError when that fails).
py::array as_array(py::handle obj, const char* name, const py::dtype& dtype, bool exact_dtype) {
    if (py::isinstance<py::array>(obj)) {
        py::array a = py::reinterpret_borrow<py::array>(obj);
        if (exact_dtype && !a.dtype().is(dtype) && !a.dtype().equal(dtype))
            throw py::type_error(std::string(name) + " must be a float64 array, got dtype " +
                                 py::str(a.dtype()).cast<std::string>() +
                                 " (dgwarp does not convert arrays: np.asarray(x, dtype=np.float64) makes a float64 copy)");
        if (!(a.flags() & py::array::c_style))
            throw py::value_error(std::string(name) +
                                  " must be C-contiguous (row-major), got a strided view; np.ascontiguousarray(x) "
                                  "makes a contiguous copy");
        return a;
    }
    if (obj.is_none()) throw py::type_error(std::string(name) + " must be an array, got None");
    try {
        return py::array(py::module_::import("numpy").attr("asarray")(obj, dtype));
    } catch (py::error_already_set& e) {
        if (e.matches(PyExc_KeyboardInterrupt) || e.matches(PyExc_MemoryError)) throw;
        throw py::type_error(std::string(name) + " must be an array of numbers, got " +
                             py::str(py::type::of(obj)).cast<std::string>() + " (" + e.what() + ")");
    }
}

void check_finite(const py::array_t<double>& a, const char* name) {
    const double* d = a.data();
    const auto n = a.size();
    for (py::ssize_t i = 0; i < n; ++i)
        if (!std::isfinite(d[i])) {
            std::string where = std::string(name) + "[";
            if (a.ndim() == 2) {
                const auto cols = a.shape(1);
                where += std::to_string(i / cols) + ", " + std::to_string(i % cols);
            } else {
                where += std::to_string(i);
            }
            throw py::value_error(where + "] is " + py::str(py::float_(d[i])).cast<std::string>() +
                                  "; every value must be finite");
        }
}

}  // namespace

py::array float_array(py::handle obj, const char* name) { return as_array(obj, name, py::dtype::of<double>(), true); }

std::string shape_text(const py::array& a) {
    std::string s = "(";
    for (py::ssize_t i = 0; i < a.ndim(); ++i) s += (i ? ", " : "") + std::to_string(a.shape(i));
    return s + (a.ndim() == 1 ? ",)" : ")");
}

py::array_t<double> float_matrix(py::handle obj, const char* name, py::ssize_t rows, py::ssize_t cols,
                                 py::ssize_t cols_alt, bool finite) {
    py::array a = as_array(obj, name, py::dtype::of<double>(), true);
    const bool ok = a.ndim() == 2 && (rows == any_rows || a.shape(0) == rows) &&
                    (a.shape(1) == cols || (cols_alt > 0 && a.shape(1) == cols_alt));
    if (!ok)
        throw py::value_error(std::string(name) + " must have shape " + dims_text(rows, cols, cols_alt) + ", got " +
                              shape_text(a));
    auto result = py::reinterpret_borrow<py::array_t<double>>(a);
    if (finite) check_finite(result, name);
    return result;
}

py::array_t<double> float_vector(py::handle obj, const char* name, py::ssize_t size, py::ssize_t size_alt) {
    py::array a = as_array(obj, name, py::dtype::of<double>(), true);
    if (a.ndim() != 1 || (a.shape(0) != size && !(size_alt > 0 && a.shape(0) == size_alt)))
        throw py::value_error(std::string(name) + " must have shape (" + std::to_string(size) +
                              (size_alt > 0 ? " or " + std::to_string(size_alt) : std::string()) + ",), got " +
                              shape_text(a));
    auto result = py::reinterpret_borrow<py::array_t<double>>(a);
    check_finite(result, name);
    return result;
}

py::array_t<double> output_matrix(py::handle obj, const char* name, py::ssize_t rows, py::ssize_t cols, bool finite) {
    if (!py::isinstance<py::array>(obj))
        throw py::type_error(std::string(name) + " must be a NumPy array (float64, shape (" + std::to_string(rows) +
                             ", " + std::to_string(cols) + ")), got " + py::str(py::type::of(obj)).cast<std::string>());
    py::array a = as_array(obj, name, py::dtype::of<double>(), true);
    if (a.ndim() != 2 || a.shape(0) != rows || a.shape(1) != cols)
        throw py::value_error(std::string(name) + " must have shape " + dims_text(rows, cols, 0) + ", got " +
                              shape_text(a));
    if (!a.writeable()) throw py::value_error(std::string(name) + " is read-only; pass a writeable array");
    auto result = py::reinterpret_borrow<py::array_t<double>>(a);
    if (finite) check_finite(result, name);
    return result;
}

std::vector<NodeId> node_ids(py::handle obj, const char* name, py::ssize_t cols, py::ssize_t* rows) {
    py::array a;
    if (py::isinstance<py::array>(obj)) {
        a = py::reinterpret_borrow<py::array>(obj);
        if (a.dtype().kind() != 'i' && a.dtype().kind() != 'u')
            throw py::type_error(std::string(name) + " must hold integer node ids, got dtype " +
                                 py::str(a.dtype()).cast<std::string>());
    } else {
        a = as_array(obj, name, py::dtype::of<std::int64_t>(), false);
    }
    const bool ok = cols == any_rows ? a.ndim() == 1 : a.ndim() == 2 && a.shape(1) == cols;
    if (!ok && !(a.size() == 0 && cols != any_rows))
        throw py::value_error(std::string(name) + " must have shape " + dims_text(any_rows, cols, 0) + ", got " +
                              shape_text(a));
    if (rows) *rows = cols == any_rows || a.size() == 0 ? a.size() / std::max<py::ssize_t>(cols, 1) : a.shape(0);
    // Any integer dtype and layout: NumPy casts to int64 (a copy, as the mesh stores its own).
    const auto ids = py::array_t<std::int64_t, py::array::c_style | py::array::forcecast>::ensure(a);
    std::vector<NodeId> out(static_cast<std::size_t>(ids.size()));
    const std::int64_t* d = ids.data();
    for (std::size_t i = 0; i < out.size(); ++i) {
        if (d[i] < std::numeric_limits<NodeId>::min() || d[i] > std::numeric_limits<NodeId>::max())
            throw py::value_error(std::string(name) + " holds node id " + std::to_string(d[i]) +
                                  ", outside the 32-bit range of node ids");
        out[i] = static_cast<NodeId>(d[i]);
    }
    return out;
}

}  // namespace dgwarp::python
