#pragma once
// Checked NumPy arguments. An ndarray is used as given, never converted
// behind the caller's back (a silent conversion would be a hidden copy every
// step): it must have the dtype asked for (else TypeError) and be
// C-contiguous, row-major (else ValueError). Lists and tuples are converted.
// Shapes are checked (ValueError naming the argument, the shape expected and
// the shape given), and so is finiteness where asked (ValueError naming the
// first bad entry).
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <cstdint>
#include <span>
#include <vector>

#include "dgwarp/mesh/mesh.hpp"

namespace dgwarp::python {

/// Any row count.
inline constexpr pybind11::ssize_t any_rows = -1;

/// `obj` as a float64 ndarray of any shape: itself when it is one (float64
/// and C-contiguous, else TypeError / ValueError), else converted (a list or
/// tuple; TypeError naming `name` when that fails).
pybind11::array float_array(pybind11::handle obj, const char* name);

/// `obj` as a float64 array of shape (rows, cols) (rows may be any_rows);
/// `cols_alt` > 0 also accepts that many columns (e.g. 2 or 3 for a 2D
/// vector). With `finite`, NaN and infinities are refused.
pybind11::array_t<double> float_matrix(pybind11::handle obj, const char* name, pybind11::ssize_t rows,
                                       pybind11::ssize_t cols, pybind11::ssize_t cols_alt = 0, bool finite = true);

/// `obj` as a float64 vector of `size` entries (finite).
pybind11::array_t<double> float_vector(pybind11::handle obj, const char* name, pybind11::ssize_t size,
                                       pybind11::ssize_t size_alt = 0);

/// An output array: float64, C-contiguous, writeable, shape (rows, cols);
/// with `finite` (an array changed in place), also finite on entry.
pybind11::array_t<double> output_matrix(pybind11::handle obj, const char* name, pybind11::ssize_t rows,
                                        pybind11::ssize_t cols, bool finite = false);

/// `obj`, an integer array (any integer dtype, any layout) of shape (any, cols)
/// (cols = any_rows: any 1D array), copied to node ids; values outside int32 are refused.
std::vector<NodeId> node_ids(pybind11::handle obj, const char* name, pybind11::ssize_t cols,
                             pybind11::ssize_t* rows = nullptr);

/// A read-only ndarray of shape `shape` viewing `data`, kept alive by `owner`.
template <class T>
pybind11::array_t<T> read_only_view(const T* data, std::vector<pybind11::ssize_t> shape, pybind11::handle owner) {
    pybind11::array_t<T> a(std::move(shape), {}, data, owner);
    pybind11::detail::array_proxy(a.ptr())->flags &= ~pybind11::detail::npy_api::NPY_ARRAY_WRITEABLE_;
    return a;
}

/// A new ndarray holding a copy of `values` with shape `shape`.
template <class T>
pybind11::array_t<T> copied_array(std::span<const T> values, std::vector<pybind11::ssize_t> shape) {
    pybind11::array_t<T> a(std::move(shape));
    std::copy(values.begin(), values.end(), a.mutable_data());
    return a;
}

/// "(5233, 2)": the shape of `a`, for messages.
std::string shape_text(const pybind11::array& a);

}  // namespace dgwarp::python
