#pragma once
// The dgwarp command-line tool: each subcommand registers itself on the app.
// Commands are thin: parse options, call the library, print, write.
#include <CLI/CLI.hpp>
#include <string>

#include "dgwarp/methods/method.hpp"

namespace dgwarp::cli {

/// Exit codes, documented in the README.
enum ExitCode : int {
    exit_ok = 0,
    exit_usage = 1,           // bad command line
    exit_bad_input = 2,       // unreadable, malformed or inconsistent input
    exit_invalid_result = 3,  // the result is invalid (inverted cells, invalid graph)
    exit_internal = 4,        // a bug or resource exhaustion (out of memory)
};

void add_quality_command(CLI::App& app);
void add_convert_command(CLI::App& app);
void add_demo_command(CLI::App& app);
void add_info_command(CLI::App& app);
void add_picture_command(CLI::App& app);
void add_deform_command(CLI::App& app);
struct DeformArgs;
/// What to try when `method` gave inverted cells (the options that apply to
/// it), leaving out what `args` already gave.
std::string invalid_result_advice(Method method, const DeformArgs& args);
void add_prepare_command(CLI::App& app);
void add_check_command(CLI::App& app);
void add_case_command(CLI::App& app);
void add_bench_command(CLI::App& app);
void add_motion_field_command(CLI::App& app);

}  // namespace dgwarp::cli
