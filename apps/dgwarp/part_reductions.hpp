#pragma once
// Under mpirun, when each process holds its own part of the mesh
// (deform_processors.hpp): the report's figures over every process's cells,
// each as one process computes it over the whole mesh. Collective: every
// process calls them, in the same order; cell ids are the whole mesh's
// (`cell_ids`: per local cell, its id in the whole mesh).
#include <cstdint>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "dgwarp/quality/mesh_quality.hpp"

namespace dgwarp::cli {

/// summarize_quality over every process's cells (`q`: one per local cell):
/// min and worst_cell (the lowest id holding the min), inverted and the
/// histogram exactly; the mean's last bits may differ from one process's (the
/// processes' compensated sums are added in another order).
QualitySummary case_quality(std::span<const double> q, const std::vector<std::int64_t>& cell_ids);

/// summarize_ratios over every process's cells, as case_quality.
RatioSummary case_ratios(std::span<const double> r, const std::vector<std::int64_t>& cell_ids);

/// worst_cells over every process: up to `count` of the cells `cells` (local
/// indices) of every process, smallest `quality` first, then the lowest id,
/// as whole-mesh ids; and their number over every process.
std::pair<std::vector<std::int64_t>, std::int64_t> case_worst(const std::vector<std::int64_t>& cells,
                                                               const std::vector<double>& quality,
                                                               const std::vector<std::int64_t>& cell_ids,
                                                               std::size_t count);

/// Every process's warnings, on rank 0 (empty elsewhere): a text every process
/// gives, once; one that only some give, prefixed by "process r: " (its counts
/// and node numbers are that process's), except a marker "with no elements" on
/// some processes (it has elements on another), dropped. `shared_nodes` (when
/// >= 0): the whole mesh's count of boundary nodes on a moving and a static
/// marker, which replaces each process's in that warning of resolve_boundary.
std::vector<std::string> case_warnings(const std::vector<std::string>& mine, std::int64_t shared_nodes = -1);

}  // namespace dgwarp::cli
