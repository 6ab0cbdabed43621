#pragma once
// `dgwarp bench`'s rows (bench_row.hpp) as Markdown (docs/RESULTS.md), JSON
// and a text table for the terminal: our figures beside the paper's.
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "dgwarp/bench/bench_row.hpp"

namespace dgwarp {

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

/// The whole report as JSON (docs/JSON.md).
nlohmann::json bench_json(const BenchInfo& info, const std::vector<BenchRow>& rows);

/// One short text table of a row, for the terminal.
std::string bench_text(const BenchRow& row);

}  // namespace dgwarp
