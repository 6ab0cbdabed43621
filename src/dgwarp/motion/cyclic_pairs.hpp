#pragma once
// Cyclic (periodic) marker pairs (CyclicMotion, docs/MOTION.md "Cyclic
// pairs"): the two halves of a periodic boundary, one the image of the other
// by a rigid motion x_B = R x_A + t (a translation, or a rotation about an
// axis: OpenFOAM's cyclic patches). A node of one half and its image on the
// other are one point of the periodic domain, so they move alike through R:
// d_B = R d_A. Where pairs meet (the edges of a box periodic in two
// directions) their nodes form one group of four, each moving as the group's
// first node does, through its own rotation.
#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "dgwarp/mesh/mesh.hpp"
#include "dgwarp/motion/node_motion.hpp"

namespace dgwarp {

/// Two markers (indices into mesh.markers), each the other's image.
struct CyclicPair {
    std::size_t first = 0, second = 0;
};

using Rotation = std::array<double, 9>;  // row-major 3 × 3

/// The nodes of cyclic markers, grouped by the images that join them.
struct CyclicGroups {
    std::vector<std::int64_t> offsets{0};  // group g: members [offsets[g], offsets[g + 1])
    std::vector<NodeId> nodes;             // per member; a group's first member is its smallest node
    std::vector<Rotation> rotations;       // per member: R with d_member = R d_first (identity for the first)
    /// Filled by resolve_boundary: per member, its index in the run's
    /// BoundarySet, and its index in the SlideSet when the step's first pass
    /// moves it (-1: a node another marker holds, which moves as that says).
    std::vector<std::int32_t> slots, slide;
    std::vector<double> origins;  // per member: its original coordinates, 3 values (z = 0 in 2D)
    std::size_t size() const { return offsets.size() - 1; }
    bool empty() const { return nodes.empty(); }
};

/// Pairs the nodes of each pair's two markers and groups them. A pair's
/// nodes are matched through its faces when element i of one marker is the
/// image of element i of the other (OpenFOAM's order for cyclic patches),
/// else as the nearest nodes under the translation between the markers'
/// centroids (any translational pair); then one rigid motion must map every
/// node to its partner, within a tenth of the markers' shortest edge.
/// Throws MeshError naming the markers and a node without a partner (or with
/// two), or markers of different node counts.
CyclicGroups cyclic_groups(const Mesh& mesh, std::span<const CyclicPair> pairs);

/// Makes the vectors (3 values per member, e.g. displacements) of each
/// group's members agree through their rotations: every member whose `held`
/// is 0 takes R_member v, where v is the first held member's vector brought
/// to the group's first node (R_held^T v_held), or, when no member is held,
/// the mean of the members' vectors brought there. Held members keep theirs.
void couple_cyclic_vectors(const CyclicGroups& groups, std::span<double> vectors, std::span<const char> held);

/// Per member of `groups` (resolved: slots, slide and origins filled): held
/// (another marker moves it: slide < 0) or not, and for a held member the
/// displacement its NodeMotion in `motion` (one per boundary slot) gives it
/// (3 values per member; zeros for the free ones, for the caller to fill).
struct CyclicVectors {
    std::vector<double> vectors;
    std::vector<char> held;
};
CyclicVectors held_cyclic_displacements(const CyclicGroups& groups, int dim, const BoundaryMotion& motion);

/// How many groups have held members whose vectors disagree through their
/// rotations by more than `tolerance` (a length); their first such member's
/// node in *node (when not null). Such a group's halves cannot move alike.
std::int64_t cyclic_disagreements(const CyclicGroups& groups, std::span<const double> vectors,
                                  std::span<const char> held, double tolerance, NodeId* node = nullptr);

}  // namespace dgwarp
