#pragma once
// The library's typed exceptions (core/error.hpp) as Python exceptions that
// carry the same message and data, and its warnings (strings) as Python
// warnings. Every class below derives from dgwarp.Error and from the
// built-in exception a Python caller expects:
//   IoError            OSError     (filename)
//   ParseError         ValueError  (file, line, expected, found)
//   MeshError          ValueError  (marker, index)
//   FormatError        ValueError
//   InvalidResultError ValueError  (count)
//   InputError         ValueError  (bad options: dgwarp::Error itself)
// Bad arguments found by the bindings (array shapes, dtypes) raise the
// built-in TypeError / ValueError directly.
#include <pybind11/pybind11.h>

#include <string>
#include <vector>

#include "dgwarp/core/warning.hpp"

namespace dgwarp::python {

/// Creates the exception and warning classes in `m` and registers the translator.
void bind_errors(pybind11::module_& m);

/// Issues `message` as a dgwarp.DgwarpWarning (warnings.warn); raises
/// (error_already_set) when the warnings filter turns it into an error.
/// Needs the GIL.
void warn(const std::string& message);
void warn_all(const std::vector<Warning>& warnings);  // their texts

}  // namespace dgwarp::python
