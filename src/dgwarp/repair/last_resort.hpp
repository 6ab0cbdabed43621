#pragma once
// dg-harmonic's last resort (docs/dg-harmonic.md): the repair that
// `dgwarp deform` and the Python package run on their own when a dg-harmonic
// step inverts cells. It is an automatic step, so it must give up quickly
// where no local repair exists: SU2's bricks with the top face turned inside
// fixed walls, the case it is for, are repaired in 1-2 rounds; a pin of SU2's
// pin array moved while its nodes on the fixed walls tear those walls (cells
// no volume motion can unfold) ran all 12 rounds the default budget allowed
// and 43 s on 10,800 nodes before failing.
#include <cstdint>
#include <optional>
#include <span>

#include "dgwarp/repair/untangle.hpp"

namespace dgwarp {

/// Rounds of the last resort: three times what the bricks need.
constexpr int last_resort_max_rounds = 6;

/// The untangle options of the last resort: inverted cells only, and of
/// them `step_folded` (UntangleOptions::cells: the cells the step folded, not
/// others the input already had at or below zero quality), viewed.
UntangleOptions last_resort_untangle_options(std::span<const std::int64_t> step_folded);

/// Runs the last resort on `points` (num_points × dim, the step's result,
/// changed in place) when the step inverted cells (`step_folded`: the cells
/// valid before and inverted now, newly_inverted_cells) and none of them has
/// every node fixed (cells_with_only_fixed_nodes: the boundary motion itself
/// folds those, and no repair of the volume can help, so nothing runs).
/// It repairs those cells (UntangleOptions::cells), not the cells the input
/// already had at or below zero quality elsewhere. Returns the untangle
/// report when it ran. Arguments as untangle's.
std::optional<UntangleReport> run_last_resort(int dim, const ElementList& cells,
                                              std::span<const std::int8_t> orientations,
                                              std::span<const NodeId> fixed_nodes,
                                              std::span<const std::int64_t> step_folded, std::span<double> points);

}  // namespace dgwarp
