#pragma once
// Sliding nodes (SlideMotion, docs/MOTION.md "Sliding"): the nodes of a
// symmetry plane or of a wall the mesh slides along stay in the planes of
// their marker's faces. Each frame gives them a displacement (a first pass:
// run/slide_pass.hpp) of which only the part in their planes is kept:
//
//   one plane at the node (3D: a face's plane; 2D: an edge's line): all but
//     the part along the plane's normal;
//   two planes (3D: a crease between two sliding planes, e.g. where a
//     symmetry plane meets a sliding floor): the part along their
//     intersection line;
//   more (3D: three planes at a corner; 2D: two lines at a corner): the node
//     cannot move, a corner (a static boundary node).
//
// A node's planes are those of the sliding faces around it, grouped: faces
// whose normals differ by less than 1e-6 rad share a plane; faces meeting at
// more than 0.5 degrees are different planes; in between the marker is curved,
// not planar, which sliding does not follow: an error naming the marker and
// the node.
#include <cstdint>
#include <span>
#include <vector>

#include "dgwarp/mesh/mesh.hpp"
#include "dgwarp/motion/cyclic_pairs.hpp"

namespace dgwarp {

/// The sliding nodes and how each may move. The nodes of cyclic markers
/// (CyclicMotion) on no other marker are among them too: the first pass moves
/// them as it moves the sliding ones, then `cyclic` couples each to its images.
struct SlideSet {
    std::vector<NodeId> nodes;          // sorted
    /// per node: 1 (in a plane), 2 (3D: along a line) or 0 (free: a cyclic
    /// marker's node on no sliding marker)
    std::vector<std::uint8_t> planes;
    std::vector<double> directions;     // per node, 3 values: the plane's unit normal (1), the line's unit direction (2), zeros (0)
    std::vector<double> origins;        // per node, dim values: its original coordinates
    std::vector<std::int32_t> slots;    // per node: its index in the run's BoundarySet (resolve_boundary sets them)
    CyclicGroups cyclic;                // the cyclic markers' nodes, grouped with their images
    bool empty() const { return nodes.empty(); }
    std::size_t size() const { return nodes.size(); }
};

/// The nodes of the sliding markers `markers` (indices into mesh.markers)
/// that are not in `pinned` (sorted: the nodes of the other markers, which
/// move or stay as those say), and the nodes among them that cannot slide.
struct SlidePlanes {
    SlideSet slides;
    std::vector<NodeId> corners;  // sorted: sliding nodes with too many planes to move (pinned)
};

/// Throws MeshError naming the marker and the node where a sliding marker is
/// curved (see above).
SlidePlanes slide_planes(const Mesh& mesh, std::span<const std::size_t> markers, std::span<const NodeId> pinned);

/// Moves every sliding node of `points` (num_points × dim) back into its
/// planes through its original position: its displacement from there keeps
/// only the part in its plane, or along its line. Exact on planes: the
/// node's distance to its plane is round-off.
void apply_slides(const SlideSet& slides, int dim, std::span<double> points);

/// The same projection on vectors, one per sliding node in `slides` order
/// (size() × dim): each keeps only its part in its plane, or along its line.
void project_slide_vectors(const SlideSet& slides, int dim, std::span<double> vectors);

}  // namespace dgwarp
