// part_reductions.hpp: the report's figures over every process's part.
#include "part_reductions.hpp"

#include <algorithm>
#include <bit>
#include <limits>
#include <unordered_map>

#include "dgwarp/core/ordered_sum.hpp"
#include "mpi_session.hpp"

namespace dgwarp::cli {

namespace {

/// This process's compensated sum of `values` (summarize_quality's, in its order).
double part_sum(std::span<const double> values) {
    OrderedSum sum;
    for (double v : values) sum.add(v);
    return sum.value();
}

/// The smallest of `values` over every process and the lowest case id of a
/// cell holding it (worst_cell: the first in the case's order).
std::pair<double, std::int64_t> case_minimum(std::span<const double> values, const std::vector<std::int64_t>& cell_ids) {
    double local = std::numeric_limits<double>::infinity();
    for (double v : values) local = std::min(local, v);
    const double min = mpi_min(local);
    std::int64_t first = std::numeric_limits<std::int64_t>::max();
    for (std::size_t i = 0; i < values.size(); ++i)
        if (values[i] == min) first = std::min(first, cell_ids[i]);
    first = mpi_min(first);
    return {min, first == std::numeric_limits<std::int64_t>::max() ? -1 : first};
}

}  // namespace

QualitySummary case_quality(std::span<const double> q, const std::vector<std::int64_t>& cell_ids) {
    QualitySummary s = summarize_quality(q);
    s.cells = mpi_sum(s.cells);
    s.inverted = mpi_sum(s.inverted);
    s.histogram.counts = mpi_sum(s.histogram.counts);
    const auto [min, worst] = case_minimum(q, cell_ids);
    s.min = s.cells > 0 ? min : 0;
    s.worst_cell = worst;
    s.mean = s.cells > 0 ? mpi_sum(std::vector<double>{part_sum(q)})[0] / static_cast<double>(s.cells) : 0;
    return s;
}

RatioSummary case_ratios(std::span<const double> r, const std::vector<std::int64_t>& cell_ids) {
    RatioSummary s;
    const std::int64_t cells = mpi_sum(static_cast<std::int64_t>(r.size()));
    const auto [min, worst] = case_minimum(r, cell_ids);
    s.min = cells > 0 ? min : 0;
    s.worst_cell = worst;
    s.mean = cells > 0 ? mpi_sum(std::vector<double>{part_sum(r)})[0] / static_cast<double>(cells) : 0;
    return s;
}

std::pair<std::vector<std::int64_t>, std::int64_t> case_worst(const std::vector<std::int64_t>& cells,
                                                               const std::vector<double>& quality,
                                                               const std::vector<std::int64_t>& cell_ids,
                                                               std::size_t count) {
    std::vector<std::pair<double, std::int64_t>> mine;
    for (std::int64_t c : cells) mine.emplace_back(quality[static_cast<std::size_t>(c)], cell_ids[static_cast<std::size_t>(c)]);
    std::sort(mine.begin(), mine.end());
    if (mine.size() > count) mine.resize(count);
    std::vector<std::int64_t> flat;
    for (const auto& [q, id] : mine) flat.insert(flat.end(), {std::bit_cast<std::int64_t>(q), id});
    const std::vector<std::int64_t> all = mpi_all_gather(flat);
    std::vector<std::pair<double, std::int64_t>> every;
    for (std::size_t k = 0; k + 1 < all.size(); k += 2) every.emplace_back(std::bit_cast<double>(all[k]), all[k + 1]);
    std::sort(every.begin(), every.end());
    if (every.size() > count) every.resize(count);
    std::vector<std::int64_t> ids;
    for (const auto& e : every) ids.push_back(e.second);
    return {ids, mpi_sum(static_cast<std::int64_t>(cells.size()))};
}

std::vector<std::string> case_warnings(const std::vector<std::string>& mine, std::int64_t shared_nodes) {
    std::string joined;
    for (const auto& w : mine) joined += w + '\x1f';
    const std::vector<std::string> all = mpi_gather_text(joined);
    const std::string shared_text = " on both a moving and a static marker; ";
    std::vector<std::vector<std::string>> by_rank(all.size());
    std::unordered_map<std::string, std::size_t> given_by;
    for (std::size_t r = 0; r < all.size(); ++r) {
        std::size_t start = 0;
        for (std::size_t end; (end = all[r].find('\x1f', start)) != std::string::npos; start = end + 1) {
            std::string w = all[r].substr(start, end - start);
            if (const auto at = w.find(shared_text); at != std::string::npos && shared_nodes >= 0)
                w = std::to_string(shared_nodes) + " boundary node" + (shared_nodes == 1 ? " is" : "s are") + w.substr(at);
            if (std::find(by_rank[r].begin(), by_rank[r].end(), w) != by_rank[r].end()) continue;
            by_rank[r].push_back(w);
            ++given_by[w];
        }
    }
    std::vector<std::string> out;
    std::unordered_map<std::string, bool> done;
    for (std::size_t r = 0; r < by_rank.size(); ++r)
        for (const std::string& w : by_rank[r]) {
            if (given_by[w] == all.size()) {
                if (!done[w]) out.push_back(w);
                done[w] = true;
            } else if (w.find("which has no elements") == std::string::npos) {
                out.push_back("process " + std::to_string(r) + ": " + w);
            }
        }
    return out;
}

}  // namespace dgwarp::cli
