#pragma once
// What a caller reads of a DG-IDW plan to cut it down, and the cut: a plan
// for the boundary nodes a step reads and every volume node, as the
// distributed prepare (mpi/distributed_prepare.cpp) makes each process's
// plan, so that a step costs nothing per boundary node of the whole mesh.
// The plan's encoding (DgIdwPlan::simplex_motion, node_simplex) stays here.
#include <cstdint>
#include <span>
#include <vector>

#include "dgwarp/methods/dg_idw.hpp"

namespace dgwarp {

/// Per boundary index of `plan`: 1 when its step reads that node's motion (a
/// moving corner of a graph simplex holding a volume node), else 0.
std::vector<std::uint8_t> dg_idw_motions_read(const DgIdwPlan& plan);

/// The shared graph vertices (DgIdwPlan::shared_offsets): per vertex, the
/// boundary indices of the nodes it stands for, ascending (the first moving
/// one gives its motion).
std::vector<std::span<const std::int32_t>> dg_idw_shared_groups(const DgIdwPlan& plan);

/// Cuts `plan` down to the boundary nodes with keep[b] (by boundary index)
/// and every volume node: the nodes not kept leave the mesh the plan is for
/// (later node ids shift down), the kept ones keep their order, so a step
/// gives the kept and the volume nodes the bits it gave them before. A
/// static corner whose node is not kept stays static (its motion is never
/// read). The shared vertices are dropped (their groups may have lost
/// nodes): the plan's step reports no conflicts, a caller counts them
/// (dg_idw_shared_groups before the cut). `kept_points`: the points of the
/// mesh left (the plan's fingerprint is made anew from them, so that a plan
/// file of it passes load_plan's checks, unless no boundary node is left: its
/// static corners then name none). Returns each old boundary index's new
/// one, or -1 when not kept.
/// Throws Error when `keep` has not a value per boundary node, when a node a
/// step reads (dg_idw_motions_read) is not kept, or when `kept_points` has
/// not the kept nodes' count × dim values.
std::vector<std::int32_t> keep_dg_idw_boundary_nodes(DgIdwPlan& plan, std::span<const std::uint8_t> keep,
                                                     std::span<const double> kept_points);

}  // namespace dgwarp
