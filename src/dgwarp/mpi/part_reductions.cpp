// part_reductions.hpp: a run's report figures over every process's part.
#include "dgwarp/mpi/part_reductions.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <limits>
#include <unordered_map>

#include <nlohmann/json.hpp>

#include "dgwarp/core/ordered_sum.hpp"
#include "dgwarp/mpi/reductions.hpp"

namespace dgwarp::mpi {

namespace {

/// This process's compensated sum of `values` (summarize_quality's, in its order).
double part_sum(std::span<const double> values) {
    OrderedSum sum;
    for (double v : values) sum.add(v);
    return sum.value();
}

/// The smallest of `values` over every process and the lowest case id of a
/// cell holding it (worst_cell: the first in the case's order).
std::pair<double, std::int64_t> minimum_over_parts(MPI_Comm comm, std::span<const double> values,
                                                   const std::vector<std::int64_t>& cell_ids) {
    double local = std::numeric_limits<double>::infinity();
    for (double v : values) local = std::min(local, v);
    const double lowest = mpi::min(comm, local);
    std::int64_t first = std::numeric_limits<std::int64_t>::max();
    for (std::size_t i = 0; i < values.size(); ++i)
        if (values[i] == lowest) first = std::min(first, cell_ids[i]);
    first = mpi::min(comm, first);
    return {lowest, first == std::numeric_limits<std::int64_t>::max() ? -1 : first};
}

}  // namespace

QualitySummary quality_over_parts(MPI_Comm comm, std::span<const double> q, const std::vector<std::int64_t>& cell_ids) {
    QualitySummary s = summarize_quality(q);
    s.cells = sum(comm, s.cells);
    s.inverted = sum(comm, s.inverted);
    s.histogram.counts = sum(comm, s.histogram.counts);
    const auto [min, worst] = minimum_over_parts(comm, q, cell_ids);
    s.min = s.cells > 0 ? min : 0;
    s.worst_cell = worst;
    s.mean = s.cells > 0 ? sum(comm, std::vector<double>{part_sum(q)})[0] / static_cast<double>(s.cells) : 0;
    return s;
}

RatioSummary ratios_over_parts(MPI_Comm comm, std::span<const double> r, const std::vector<std::int64_t>& cell_ids) {
    RatioSummary s;
    const std::int64_t cells = sum(comm, static_cast<std::int64_t>(r.size()));
    const auto [min, worst] = minimum_over_parts(comm, r, cell_ids);
    s.min = cells > 0 ? min : 0;
    s.worst_cell = worst;
    s.mean = cells > 0 ? sum(comm, std::vector<double>{part_sum(r)})[0] / static_cast<double>(cells) : 0;
    return s;
}

std::pair<std::vector<std::int64_t>, std::int64_t> worst_over_parts(MPI_Comm comm,
                                                                     const std::vector<std::int64_t>& cells,
                                                                     const std::vector<double>& quality,
                                                                     const std::vector<std::int64_t>& cell_ids,
                                                                     std::size_t count) {
    std::vector<std::pair<double, std::int64_t>> mine;
    for (std::int64_t c : cells) mine.emplace_back(quality[static_cast<std::size_t>(c)], cell_ids[static_cast<std::size_t>(c)]);
    std::sort(mine.begin(), mine.end());
    if (mine.size() > count) mine.resize(count);
    std::vector<std::int64_t> flat;
    for (const auto& [q, id] : mine) flat.insert(flat.end(), {std::bit_cast<std::int64_t>(q), id});
    const std::vector<std::int64_t> all = all_gather(comm, flat);
    std::vector<std::pair<double, std::int64_t>> every;
    for (std::size_t k = 0; k + 1 < all.size(); k += 2) every.emplace_back(std::bit_cast<double>(all[k]), all[k + 1]);
    std::sort(every.begin(), every.end());
    if (every.size() > count) every.resize(count);
    std::vector<std::int64_t> ids;
    for (const auto& e : every) ids.push_back(e.second);
    return {ids, sum(comm, static_cast<std::int64_t>(cells.size()))};
}

std::vector<Warning> warnings_over_parts(MPI_Comm comm, const std::vector<Warning>& mine, std::int64_t shared_nodes,
                                         SharedNodeRule rule) {
    // Each process's warnings as JSON (code, text and data), gathered on rank 0.
    nlohmann::json sent = nlohmann::json::array();
    for (const Warning& w : mine)
        sent.push_back({static_cast<int>(w.code), w.text, w.marker, w.count, w.node, w.element,
                        std::isnan(w.value) ? nlohmann::json(nullptr) : nlohmann::json(w.value)});
    const std::vector<std::string> all = gather_text(comm, sent.dump());
    const auto text_of = [](const Warning& w) { return std::to_string(static_cast<int>(w.code)) + ':' + w.text; };
    std::vector<std::vector<Warning>> by_rank(all.size());
    std::unordered_map<std::string, std::size_t> given_by;
    for (std::size_t r = 0; r < all.size(); ++r)
        for (const auto& item : nlohmann::json::parse(all[r])) {
            Warning w{static_cast<WarningCode>(item[0].get<int>()), item[1].get<std::string>(),
                      item[2].get<std::string>(), item[3].get<std::int64_t>()};
            w.node = item[4].get<std::int64_t>();
            w.element = item[5].get<std::int64_t>();
            if (!item[6].is_null()) w.value = item[6].get<double>();
            // The whole mesh's count of nodes on a moving and a static marker, not each process's.
            if (w.code == WarningCode::shared_moving_static && shared_nodes >= 0) w = shared_nodes_warning(shared_nodes, rule);
            const std::string key = text_of(w);
            if (std::any_of(by_rank[r].begin(), by_rank[r].end(), [&](const Warning& o) { return text_of(o) == key; }))
                continue;
            by_rank[r].push_back(w);
            ++given_by[key];
        }
    std::vector<Warning> out;
    std::unordered_map<std::string, bool> done;
    for (std::size_t r = 0; r < by_rank.size(); ++r)
        for (Warning& w : by_rank[r]) {
            const std::string key = text_of(w);
            if (given_by[key] == all.size()) {
                if (!done[key]) out.push_back(w);
                done[key] = true;
            } else if (w.code != WarningCode::empty_named_marker) {  // it has elements on another process
                w.text = "process " + std::to_string(r) + ": " + w.text;
                out.push_back(std::move(w));
            }
        }
    return out;
}

}  // namespace dgwarp::mpi
