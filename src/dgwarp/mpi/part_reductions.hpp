#pragma once
// When each process holds its own part of the mesh (a solver's partition, a
// decomposed OpenFOAM case): a run's report figures over every process's
// cells, each as one process computes it over the whole mesh. Collective:
// every process of `comm` calls them, in the same order; cell ids are the
// whole mesh's (`cell_ids`: per local cell, its id in the whole mesh).
#include <mpi.h>

#include <cstdint>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "dgwarp/core/warning.hpp"
#include "dgwarp/motion/resolve_motion.hpp"
#include "dgwarp/quality/mesh_quality.hpp"

namespace dgwarp::mpi {

/// summarize_quality over every process's cells (`q`: one per local cell):
/// min and worst_cell (the lowest id holding the min), inverted and the
/// histogram exactly; the mean's last bits may differ from one process's (the
/// processes' compensated sums are added in another order).
QualitySummary quality_over_parts(MPI_Comm comm, std::span<const double> q, const std::vector<std::int64_t>& cell_ids);

/// summarize_ratios over every process's cells, as quality_over_parts.
RatioSummary ratios_over_parts(MPI_Comm comm, std::span<const double> r, const std::vector<std::int64_t>& cell_ids);

/// worst_cells over every process: up to `count` of the cells `cells` (local
/// indices) of every process, smallest `quality` first, then the lowest id,
/// as whole-mesh ids; and their number over every process.
std::pair<std::vector<std::int64_t>, std::int64_t> worst_over_parts(MPI_Comm comm,
                                                                     const std::vector<std::int64_t>& cells,
                                                                           const std::vector<double>& quality,
                                                                     const std::vector<std::int64_t>& cell_ids,
                                                                     std::size_t count);

/// Every process's warnings, on rank 0 of `comm` (empty elsewhere): one every process
/// gives (same code and text), once; one that only some give, its text
/// prefixed by "process r: " (its counts and node numbers are that
/// process's), except a marker without elements on some processes
/// (WarningCode::empty_named_marker: it has elements on another), dropped.
/// `shared_nodes` (when >= 0): the whole mesh's count of boundary nodes on a
/// moving and a static marker, which replaces each process's warning of
/// resolve_boundary about them (shared_nodes_warning with `rule`).
std::vector<Warning> warnings_over_parts(MPI_Comm comm, const std::vector<Warning>& mine,
                                         std::int64_t shared_nodes = -1,
                                         SharedNodeRule rule = SharedNodeRule::moving_wins);

}  // namespace dgwarp::mpi
