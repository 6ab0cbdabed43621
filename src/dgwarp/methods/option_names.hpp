#pragma once
// The method options by name, and the method each belongs to: one table for
// the CLI's flags (--a-translation) and the Python package's keyword
// arguments (a_translation), so that both refuse an option of another method
// than the one that runs (it would be silently ignored) in the same way.
#include <optional>
#include <string_view>

#include "dgwarp/methods/method.hpp"

namespace dgwarp {

struct MethodOptionName {
    std::string_view name;  // as the CLI's flag without "--"; Python writes '_' for '-'
    Method method;          // the method it acts on (MethodOptions' member of that method)
};

/// Every method option, grouped by method in all_methods order.
inline constexpr MethodOptionName method_option_names[] = {
    {"a-translation", Method::dg_idw},        {"a-rotation", Method::dg_idw},
    {"length-scale", Method::dg_idw},         {"dg-idw-weights", Method::dg_idw},
    {"dgm-substep", Method::dgm},             {"idw-moving-exponent", Method::idw},
    {"idw-static-exponent", Method::idw},     {"rbf-radius", Method::rbf},
    {"rbf-greedy", Method::rbf},              {"harmonic-wall-spacing", Method::dg_harmonic},
    {"harmonic-growth", Method::dg_harmonic}, {"harmonic-redo-below", Method::dg_harmonic},
    {"laplacian-increments", Method::laplacian},
    {"laplacian-exponent", Method::laplacian},   {"laplacian-model", Method::laplacian},
};

/// The method option `name` belongs to: `name` as in the table, with or
/// without a leading "--", and with '_' or '-' between words; nullopt for a
/// name that is not a method option.
std::optional<Method> option_method(std::string_view name);

/// Sets the method option `name` (as option_method takes it) of `options`
/// from its text `value`, as the CLI's flag reads it: a number (C locale),
/// `auto` for length-scale, `paper` or `continuous` for dg-idw-weights,
/// `elasticity` or `laplacian` for laplacian-model, a whole number 1-64 for
/// laplacian-increments, and for dgm-substep a switch (true/false, on/off,
/// yes/no, 1/0). For callers that hold options as text: OpenFOAM's
/// dictionary (the motion solver), a configuration file. Throws Error naming
/// the option and the value for an unknown option or a value it cannot take;
/// the ranges of numbers are checked by prepare, as for the CLI.
void set_method_option(MethodOptions& options, std::string_view name, std::string_view value);

}  // namespace dgwarp
