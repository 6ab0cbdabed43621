#pragma once
// dg-harmonic's last resort (repair/last_resort.hpp) when each process holds
// its own part of the mesh: the cells around those the step folded, from
// every process, make one small mesh that every process repairs alike, and
// each takes the new coordinates of the nodes it holds. Collective: every
// process of `comm` calls it.
//
// The repair is local: round r of the last resort (at most
// last_resort_max_rounds) moves the free nodes within r - 1 rings of the
// cells it mends (the folded ones, and those its moves bring to or below zero
// quality), measures the cells around them and
// smooths the region with its neighbours; the patch holds every cell within
// part_repair_rings rings of those (so that every node the repair can move or
// read has all its cells), nodes and cells numbered in the whole mesh's
// order. The nodes at the patch's edge are held, as the boundary's are. So
// each node moves as one process's last resort over the whole mesh moves it
// (tested bit for bit on a decomposed OpenFOAM case), unless the repair
// reaches beyond part_repair_max_rings rings (then it is a valid repair of
// its own, not one process's to the bit). Its report counts every cell, as
// one process's does (each cell held by one process; those outside the patch
// do not change).
#include <mpi.h>

#include <cstdint>
#include <optional>
#include <span>

#include "dgwarp/mesh/mesh.hpp"
#include "dgwarp/repair/untangle.hpp"

namespace dgwarp::mpi {

/// Rings of cells around the cells to mend that the patch holds at first:
/// the last resort's rounds, and two more (the cells around a moved node,
/// the neighbours the smoothing reads). A repair that moved a node within
/// reach of the held edge (it mends the cells a move inverts too) is run
/// again on a patch grown to hold its reach, up to part_repair_max_rings.
inline constexpr int part_repair_rings = 8;
inline constexpr int part_repair_max_rings = 64;

/// run_last_resort over every process's part. `mesh`: this process's part
/// (its cells over its local nodes), `own_orientation` per local cell (as
/// OriginalCells::own_orientation), `node_ids` and `cell_ids` per local node
/// and cell their ids in the whole mesh (a node held by several processes has
/// one id, and the same coordinates on each), `fixed`: the local boundary
/// nodes, `folded`: the local cells the step inverted (newly_inverted_cells),
/// `points`: this process's coordinates of the frame, changed in place.
/// Returns the repair's report (the same on every process) when it ran:
/// something was folded on some process, and no folded cell has every node
/// fixed. Throws on every process alike (mpi/agreement.hpp).
std::optional<UntangleReport> last_resort_over_parts(MPI_Comm comm, const Mesh& mesh,
                                                     std::span<const std::int8_t> own_orientation,
                                                     std::span<const std::int64_t> node_ids,
                                                     std::span<const std::int64_t> cell_ids,
                                                     std::span<const NodeId> fixed,
                                                     std::span<const std::int64_t> folded, std::span<double> points);

}  // namespace dgwarp::mpi
