#pragma once
// Internal: prepare_dg_harmonic with the coarse points given, for the
// distributed prepare (dgwarp/mpi), which selects them over all processes
// (coarse_points.hpp's stages) and then builds the same plan on every one.
#include <cstdint>
#include <span>

#include "dgwarp/methods/dg_harmonic.hpp"

namespace dgwarp {

/// prepare_dg_harmonic, with `coarse` (volume node ids, ascending in the
/// order select_coarse_points returns them) as the coarse level's interior
/// points instead of selecting them. stats.select_seconds stays 0.
/// `volume_morton`: morton_order of the volume nodes, when the caller has it
/// (build_located_graph's GraphOptions::morton).
DgHarmonicPlan prepare_dg_harmonic_on_coarse(int dim, std::span<const double> points, const BoundarySet& boundary,
                                             std::span<const NodeId> coarse, const DgHarmonicOptions& options,
                                             const ProgressFn& progress = {},
                                             std::span<const std::uint32_t> volume_morton = {});

}  // namespace dgwarp
