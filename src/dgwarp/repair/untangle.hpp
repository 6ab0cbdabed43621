#pragma once
// Local repair of a deformed mesh: moves the volume nodes around inverted
// cells until no cell is inverted (or the budget runs out), leaving every
// other node, and every boundary node, exactly where the deformation put it.
//
// An opt-in step after any method's deform, for the motions no single-pass
// interpolation can follow (a face turning inside fixed walls, SU2's brick
// meshes): deform, count inverted cells, and when there are some, untangle.
// It is not part of a method's one pass per step, and costs nothing when no
// cell is inverted.
//
// The algorithm (docs/UNTANGLE.md): the free nodes of the inverted cells, and
// round by round one more ring of their neighbours, are each moved in turn
// (Gauss-Seidel, in node order) by a compass search that maximises the
// smallest Knupp shape quality of the cells around the node (optimisation-based
// smoothing, Freitag & Plassmann); after a round that gained nothing, the
// region is first smoothed (Laplacian), which unfolds bands of flipped cells
// that no single node can leave, and the round is undone if that did not help.
// The quality is signed against the reference orientations, so a node leaves
// an inverted cell by raising its quality through zero. Serial and deterministic.
#include <cstdint>
#include <span>
#include <vector>

#include "dgwarp/mesh/mesh.hpp"

namespace dgwarp {

struct UntangleOptions {
    double target_quality = 0;  // repair the cells at or below this quality (0: the inverted ones); in [0, 1)
    int max_rounds = 30;        // round r moves the free nodes within r - 1 rings of the cells to repair;
                                //   it stops early when two rounds in a row repair no cell and lift the worst by under 0.001
    int sweeps_per_round = 4;   // Gauss-Seidel sweeps over those nodes per round
    int max_steps = 40;         // search steps per node and sweep
    /// The cells to repair (any order); empty: every cell at or below
    /// target_quality. Given, the others at or below it are left as they are
    /// unless a move of the repair reaches them (their nodes' neighbours).
    std::span<const std::int64_t> cells{};
};

struct UntangleReport {
    std::int64_t inverted_before = 0;      // cells with quality <= 0 on entry
    std::int64_t inverted_after = 0;       // and on return (0: no cell is inverted)
    std::int64_t below_target_before = 0;  // cells with quality <= target_quality on entry
    std::int64_t below_target_after = 0;   // and on return (cells whose nodes are all fixed cannot change)
    std::int64_t nodes_moved = 0;      // nodes that ended somewhere else
    double max_move = 0;               // largest distance a node moved (mesh units)
    int rounds = 0;                    // rounds run (0 when no cell needed repair)
    double min_quality_after = 1;      // smallest quality of the cells around the nodes it tried to move (1: none)
};

/// Repairs inverted cells of `points` (num_points × dim, deformed coordinates,
/// changed in place). `cells` and `orientations` (cell_orientations of the
/// undeformed mesh, one per cell) say which cells exist and how each was
/// oriented; `fixed_nodes` (sorted or not) never move: pass every boundary
/// node, so the boundary stays exactly where its motion put it.
/// Throws MeshError when the sizes do not match or a node id is out of range,
/// Error for a target quality outside [0, 1).
UntangleReport untangle(int dim, const ElementList& cells, std::span<const std::int8_t> orientations,
                        std::span<const NodeId> fixed_nodes, std::span<double> points,
                        const UntangleOptions& options = {});

/// The cells untangle sets out to repair with the same arguments (ascending):
/// those at or below options.target_quality with a node that is not fixed
/// (of options.cells, when given). `census`, when given, gets the report's
/// counts on entry (inverted_before, below_target_before: of every cell).
/// Throws as untangle.
std::vector<std::int64_t> cells_to_untangle(int dim, const ElementList& cells, std::span<const std::int8_t> orientations,
                                            std::span<const NodeId> fixed_nodes, std::span<const double> points,
                                            const UntangleOptions& options = {}, UntangleReport* census = nullptr);

}  // namespace dgwarp
