#include "flag_values.hpp"

#include "dgwarp/core/error.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>

#include "dgwarp/core/parallel_for.hpp"

namespace dgwarp::cli {

namespace {

/// A number for a message: "16", "0.99", "1e+06".
std::string flag_number_text(double x) {
    char text[32];
    std::snprintf(text, sizeof text, "%g", x);
    return text;
}

/// Validator of real numbers: `ok` says whether a finite value is accepted;
/// `expected` names what is ("a positive number").
CLI::Validator real_validator(const std::string& expected, std::function<bool(double)> ok) {
    return CLI::Validator(
        [expected, ok](std::string& text) -> std::string {
            double value = 0;
            if (!CLI::detail::lexical_cast(text, value) || !std::isfinite(value) || !ok(value))
                return "expected " + expected + ", got " + text;
            return {};
        },
        "", "");
}

}  // namespace

CLI::Validator positive_number() {
    return real_validator("a positive number", [](double x) { return x > 0; });
}

CLI::Validator number_between(double low, double high) {
    return real_validator("a number from " + flag_number_text(low) + " to " + flag_number_text(high),
                          [low, high](double x) { return x >= low && x <= high; });
}

CLI::Validator finite_number() {
    return real_validator("a finite number", [](double) { return true; });
}

CLI::Validator one_of(const std::vector<std::string>& names, const std::string& what) {
    std::string list;
    for (const auto& n : names) list += (list.empty() ? "" : ", ") + n;
    return CLI::Validator(
        [names, what, list](std::string& text) -> std::string {
            if (std::find(names.begin(), names.end(), text) != names.end()) return {};
            return "expected " + what + ": one of " + list + "; got '" + text + "'";
        },
        "", "");
}

CLI::Validator whole_number_between(long long low, long long high) {
    const std::string expected = "a whole number from " + std::to_string(low) + " to " + std::to_string(high);
    return CLI::Validator(
        [expected, low, high](std::string& text) -> std::string {
            long long value = 0;
            if (!CLI::detail::lexical_cast(text, value) || value < low || value > high)
                return "expected " + expected + ", got " + text;
            return {};
        },
        "", "");
}

CLI::Validator positive_whole_number() {
    return CLI::Validator(
        [](std::string& text) -> std::string {
            int value = 0;
            if (!CLI::detail::lexical_cast(text, value) || value < 1)
                return "expected a whole number >= 1, got " + text;
            return {};
        },
        "", "");
}

CLI::Option* add_threads_option(CLI::App* cmd, int& threads, const std::string& default_text) {
    const int most = max_threads();
    const int cores = available_cores();
    const std::string limit = "at most " + std::to_string(most) + " (4 per core, and at least 64; this machine has " +
                              std::to_string(cores) + " core" + (cores == 1 ? "" : "s") +
                              ": more threads than cores are not faster)";
    return cmd->add_option("--threads", threads,
                           "Threads to use, 1 to " + std::to_string(most) + " (default: " + default_text + ")")
        ->check(CLI::Validator(
            [most, limit](std::string& text) -> std::string {
                long long value = 0;
                if (!CLI::detail::lexical_cast(text, value) || value < 1)
                    return "expected a whole number of threads >= 1, got " + text;
                if (value > most) return limit + ", got " + text;
                return {};
            },
            "", ""));
}

void use_threads(int threads) {
    if (threads > 0)
        set_num_threads(threads);
    else if (num_threads() > max_threads())
        set_num_threads(max_threads());
}

CLI::Option* add_rename_marker_option(CLI::App* cmd, std::vector<std::string>& renames) {
    return cmd
        ->add_option("--rename-marker", renames,
                     "OLD=NEW: the mesh's marker OLD is called NEW from reading on (the motion file and the outputs "
                     "name it NEW; repeat for several)")
        ->check(CLI::Validator([](std::string& text) { return marker_rename_problem(text); }, "OLD=NEW", ""));
}

void apply_marker_renames(Mesh& mesh, const std::vector<std::string>& values) {
    for (const std::string& v : values) {
        try {
            rename_markers(mesh, {parse_marker_rename(v)});
        } catch (const MeshError& e) {
            throw MeshError("--rename-marker '" + v + "': " + e.what(), e.marker(), e.index());
        }
    }
}

}  // namespace dgwarp::cli
