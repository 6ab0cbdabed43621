#pragma once
// The motion of every node of every marker in one frame, before the
// shared-node rule decides what nodes on several markers do. Checks that each
// marker's motion fits the mesh: node files cover exactly their markers'
// nodes, coordinates per node match the mesh dimension, and 2D motions stay in
// the xy plane (rotation about z only).
#include <span>
#include <string_view>
#include <vector>

#include "dgwarp/mesh/mesh.hpp"
#include "dgwarp/motion/motion_spec.hpp"

namespace dgwarp {

/// For each marker m of `mesh`: the motion of each of its nodes
/// `marker_nodes[m]` (sorted ids, from marker_nodes()) under `motions[m]` at
/// time `time` (used by periodic motions); an empty vector for a FixedMotion.
/// A node file may serve several markers (SU2 writes one surface file for all
/// moving markers): those that share a file (same kind and source; for tables
/// built in code, the same object) must together hold exactly its nodes.
/// `where` prefixes messages ("motion.json, frame 2").
/// Throws MeshError (marker name; index = the node id when one node is at
/// fault) when a marker node is missing from its file, a file node is not a
/// node of the mesh or not on the markers using the file, a file gives 2
/// coordinates per node for a 3D mesh, or a 2D motion leaves the xy plane.
std::vector<std::vector<NodeMotion>> marker_node_motions(const Mesh& mesh,
                                                         std::span<const std::vector<NodeId>> marker_nodes,
                                                         std::span<const MarkerMotion* const> motions,
                                                         double time, std::string_view where);

}  // namespace dgwarp
