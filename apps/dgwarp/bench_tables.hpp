#pragma once
// `dgwarp bench`: the paper's values (Tables 1-10) and the results of one
// run, as plain data, and their Markdown / JSON / text renderings.
#include <array>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "dgwarp/methods/method.hpp"
#include "dgwarp/quality/mesh_quality.hpp"

namespace dgwarp::cli {

/// One method's figures in the paper; unset = not given.
struct PaperFigures {
    std::optional<double> mean, min, seconds;
    bool failed = false;  // the paper's "-": no valid mesh
    bool not_run = false; // the paper's "-" in Table 9: too costly to run
};

/// The paper's values for one case, size and motion.
struct PaperEntry {
    std::string tables;                     // "Tables 1-3"
    std::array<PaperFigures, 4> methods;    // in all_methods order: dg-idw, dgm, idw, rbf
    std::optional<double> original_mean, original_min;
};

/// The paper's figures of `method` in `entry` (unset for a method the paper did not run, e.g. dg-harmonic).
PaperFigures paper_figures(const PaperEntry& entry, Method method);

/// The paper's entry for (case, size, motion), or nullopt.
std::optional<PaperEntry> paper_entry(const std::string& case_name, int size, const std::string& motion);

/// What one method did on one case and motion.
struct MethodResult {
    Method method = Method::dg_idw;
    std::string label;          // the method's name, or a variant ("dg-idw L=auto"): no paper figures
    std::string status = "ok";  // "ok", "skipped: why", "failed: why"
    bool ran = false;           // quality and times are set
    double prepare_seconds = 0, step_seconds = 0;
    QualitySummary quality;
};

/// One case, size and motion with every method.
struct BenchRow {
    std::string case_name;
    int size = 0;
    std::string motion, motion_description;
    std::size_t nodes = 0, cells = 0, boundary_nodes = 0, moving_nodes = 0;
    QualitySummary original;
    std::vector<MethodResult> methods;
    std::optional<PaperEntry> paper;
    std::vector<std::string> pictures;  // PNG paths relative to the Markdown file
};

/// Where and how the run was made.
struct BenchInfo {
    std::string machine, date, commit;
    int threads = 1;
    bool quick = false;
    double total_seconds = 0;
};

/// The whole report as Markdown: a header (machine, date, commit, options),
/// then one table per row: ours beside the paper's.
std::string bench_markdown(const BenchInfo& info, const std::vector<BenchRow>& rows);

/// A line in a --markdown file from which on `dgwarp bench` keeps what the file
/// holds, below the tables it writes (sections other tools write, by hand or by
/// script: bench/peers/openfoam.sh's table in docs/RESULTS.md).
inline constexpr const char* bench_kept_marker = "<!-- dgwarp bench keeps what follows -->";

/// The whole report as JSON.
nlohmann::json bench_json(const BenchInfo& info, const std::vector<BenchRow>& rows);

/// One short text table of a row, for the terminal.
std::string bench_text(const BenchRow& row);

}  // namespace dgwarp::cli
