#pragma once
// Checks of numeric flag values, run while the command line is parsed: a bad
// value is a usage error (exit 1) before any work starts, with a message that
// says what was expected in plain numbers (CLI11's Range validators print
// DBL_MAX in full, and its PositiveNumber lets nan through).
#include <CLI/CLI.hpp>
#include <string>
#include <vector>

#include "dgwarp/io/marker_names.hpp"

namespace dgwarp::cli {

/// A finite number > 0.
CLI::Validator positive_number();
/// A finite number in [low, high].
CLI::Validator number_between(double low, double high);
/// Any finite number.
CLI::Validator finite_number();
/// One of `names` ("expected one of a, b, c; got d"); `what` names them ("a case").
CLI::Validator one_of(const std::vector<std::string>& names, const std::string& what);
/// A whole number in [low, high].
CLI::Validator whole_number_between(long long low, long long high);
/// A whole number >= 1 (counts, 1-based zones).
CLI::Validator positive_whole_number();

/// Adds --rename-marker OLD=NEW (repeatable; checked while parsing) to `cmd`.
CLI::Option* add_rename_marker_option(CLI::App* cmd, std::vector<std::string>& renames);

/// Renames `mesh`'s markers as --rename-marker's `values` say; a MeshError
/// names the option and the value at fault.
void apply_marker_renames(Mesh& mesh, const std::vector<std::string>& values);

/// Adds --threads to `cmd`, checked to be 1 .. max_threads() (the message
/// names the limit and the machine's cores). `default_text` says what is
/// used when it is not given ("all cores").
CLI::Option* add_threads_option(CLI::App* cmd, int& threads, const std::string& default_text);

/// Sets the thread count of the library's loops: `threads` when > 0;
/// otherwise OpenMP's default (all cores, or OMP_NUM_THREADS), clamped to
/// max_threads() so that an environment asking for too many cannot crash it.
void use_threads(int threads);

}  // namespace dgwarp::cli
