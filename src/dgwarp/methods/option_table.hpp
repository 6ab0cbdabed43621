#pragma once
// Every method option in one table: its name, the method it acts on, what
// values it takes, its key in the JSON report, whether a plan keeps it, its
// help text, and how it reads and writes MethodOptions. The CLI's flags,
// the Python package's keyword arguments, the JSON report, the OpenFOAM
// motion solver's dictionary, the options sent between MPI processes and
// their fingerprint are all made from it: adding an option is a member of its
// method's options and a row here. Tuning rows (the methods' internal
// constants, measured once: docs/dg-harmonic.md, docs/laplacian.md) are
// not CLI flags, Python keywords nor report keys, but travel and compare
// with the others, and set_method_option sets them.
#include <array>
#include <optional>
#include <string>
#include <string_view>

#include "dgwarp/methods/method.hpp"

namespace dgwarp {

enum class OptionKind {
    number,          // a finite number from low to high (low excluded when low_open)
    whole_number,    // a whole number from low to high
    number_or_auto,  // a number from low to high, or "auto" (the method chooses)
    word,            // one of `words`
    on_off,          // true or false (on/off, yes/no, 1/0); the CLI's flag takes no value
};

/// A value of an option: `number` for the number kinds and on_off (1 or 0),
/// `word` for a word (one of the row's words), `automatic` for "auto".
struct OptionValue {
    double number = 0;
    std::string_view word;
    bool automatic = false;
};

struct MethodOption {
    std::string_view name;        // the CLI's flag without "--"; Python's keyword writes '_' for '-'
    Method method;                // the method it acts on (its member of MethodOptions)
    OptionKind kind;
    std::string_view report_key;  // its key in the JSON report's "options"
    bool kept_by_plan;            // acts at prepare time: a plan (and a plan file) keeps it
    double low = 0, high = 0;     // number, whole_number: the range
    bool low_open = false;        // number, number_or_auto: low itself is refused
    std::array<std::string_view, 3> words{};  // word: the values it takes (the unused ones empty)
    std::string_view help;        // what it does (the CLI's --help, the docs)
    OptionValue (*get)(const MethodOptions&) = nullptr;
    void (*set)(MethodOptions&, const OptionValue&) = nullptr;
    bool tuning = false;          // a method's internal constant: no flag, keyword nor report key
};

/// Every method option, grouped by method in all_methods order.
extern const std::array<MethodOption, 27> method_option_table;

/// The row of `name`: as in the table, with or without a leading "--", and
/// with '_' or '-' between words; nullptr for a name that is not a method option.
const MethodOption* find_method_option(std::string_view name);

/// The method option `name` belongs to (find_method_option), or nullopt.
std::optional<Method> option_method(std::string_view name);

/// What `option` takes, for messages: "a number from 1e-06 to 1e+06",
/// "'paper' or 'continuous'", ...
std::string expected_values(const MethodOption& option);

/// The value of `text` for `option`, as the CLI's flag reads it: a number
/// (C locale), `auto` for number_or_auto, a word of the row, for on_off
/// true/false, on/off, yes/no or 1/0. Throws UsageError "method option NAME:
/// expected ..., got 'TEXT'" for a value out of its range or of another form;
/// with `check_range` false, any number (NaN and infinities too) of a number
/// kind is taken as it is (the methods' prepare refuses it).
OptionValue parse_option_value(const MethodOption& option, std::string_view text, bool check_range = true);

/// `option`'s value in `options` as parse_option_value reads it back: numbers
/// in their shortest exact form, "auto", a word, "true" or "false".
std::string option_text(const MethodOption& option, const MethodOptions& options);

/// Sets the method option `name` (find_method_option) of `options` from its
/// text (parse_option_value). For callers that hold options as text:
/// OpenFOAM's dictionary (the motion solver), a configuration file, the MPI
/// processes. Throws UsageError naming the option (and the options there are,
/// for an unknown name) or the value.
void set_method_option(MethodOptions& options, std::string_view name, std::string_view text);

/// Every option of `options` as "name value" lines in table order, and back
/// (options not named keep their defaults): the options exactly, as text,
/// whatever their values (ranges are not checked: the methods' prepare
/// refuses what it cannot take, on every process alike). Throws UsageError
/// for an unknown name or a value of another form.
std::string method_options_text(const MethodOptions& options);
MethodOptions method_options_from_text(std::string_view text);

/// The options a run with `plan` uses: `run`'s, but those of the plan's
/// method that a plan keeps (kept_by_plan: they acted at its prepare) are the
/// plan's own. What a plan loaded from a file, a pickle or a distributed plan
/// file runs with; the step-time options (dg-harmonic's guard) stay the run's.
/// Only DG-IDW's and DG-harmonic's plans hold their options (the plans that
/// are saved); for the other methods, `run`'s whole.
MethodOptions options_with_plan(const Plan& plan, const MethodOptions& run);

}  // namespace dgwarp
