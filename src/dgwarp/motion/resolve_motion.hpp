#pragma once
// From a motion spec to per-node motions: which boundary nodes move, and how
// each moves in frame k. The rules (docs/MOTION.md):
//  - a marker is *moving* when some frame gives it a motion other than
//    "fixed" (even one that is zero in that frame, such as step 0 of a
//    pitching motion or the zero-displacement rim of a bump); otherwise static.
//  - a boundary node is moving when it is on a moving marker, except, under
//    SharedNodeRule::static_wins, when it is also on a static marker. This
//    flag does not change from frame to frame (the DG-IDW weights depend on it).
//  - a node on several moving markers takes their common motion; they must
//    agree: the same NodeMotion, or new positions within the tolerance
//    (spec.shared_tolerance, default 1e-9 × the mesh's bounding-box diagonal).
//    When they agree only by position, the node takes the motion of the first
//    of those markers in mesh order. Disagreement is an error naming the
//    markers and the number of nodes, except for nodes that static_wins holds
//    fixed.
//  - static nodes get the zero motion (t = 0, w = 0, c = 0).
//  - warnings (core/warning.hpp: codes and texts, nothing here prints): a marker moving a node farther
//    than the mesh's bounding-box diagonal, nodes on moving and static
//    markers, boundary nodes at the same coordinates (zero-length boundary
//    edges), a marker the motion names that has no elements, no moving
//    marker at all (an empty or all-fixed motion: nothing moves), boundary
//    faces the motion itself turns over (against their nodes' mean rotation).
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "dgwarp/core/warning.hpp"
#include "dgwarp/mesh/mesh.hpp"
#include "dgwarp/motion/motion_spec.hpp"
#include "dgwarp/motion/slide_planes.hpp"
#include "dgwarp/motion/node_motion.hpp"

namespace dgwarp {

/// What every frame of one (mesh, motion) pair shares: built once by
/// resolve_boundary, so that resolve_frame does not look at the other frames
/// and a series of F frames costs O(F), not O(F²). Plain data for
/// resolve_frame; callers need not read it.
struct SeriesContext {
    std::vector<std::vector<NodeId>> marker_nodes;  // per mesh marker: its nodes, sorted
    std::vector<std::vector<std::int32_t>> slots;   // per marker node: its index in the BoundarySet
    std::vector<char> marker_moving;                // per mesh marker: 1 when some frame moves it
    std::vector<char> marker_sliding;               // per mesh marker: 1 when it slides (SlideMotion)
    std::vector<char> marker_cyclic;                // per mesh marker: 1 when it is cyclic (CyclicMotion)
    double diagonal = 0;                            // of the mesh's bounding box
    double tolerance = 0;                           // for new positions of shared nodes to agree
};

/// The boundary of a motion problem and how its markers were classified.
struct ResolvedBoundary {
    BoundarySet boundary;                     // every node of every marker, sorted; moving flags
    std::vector<std::string> moving_markers;  // in mesh order
    std::vector<std::string> static_markers;  // in mesh order
    /// Sliding markers (SlideMotion), in mesh order. Their nodes on no other
    /// marker are `slides` (moving boundary nodes whose motion each frame's
    /// first pass gives: run/slide_pass.hpp), but where too many planes meet
    /// (static).
    std::vector<std::string> sliding_markers;
    /// Cyclic markers (CyclicMotion), in mesh order. Their nodes on no other
    /// marker are in `slides` too (free, planes 0, unless also on a sliding
    /// marker); slides.cyclic couples every cyclic node to its images.
    std::vector<std::string> cyclic_markers;
    SlideSet slides;
    std::vector<Warning> warnings;            // e.g. nodes shared by moving and static markers
    SeriesContext context;                    // what resolve_frame reuses for every frame
};

/// Throws MeshError (naming the marker, and listing the mesh's markers) when
/// a frame of `spec` names a marker `mesh` does not have. resolve_boundary
/// checks it; a caller resolving frames of another spec against a
/// ResolvedBoundary (the Python package's plans) checks it with this.
void check_marker_names(const Mesh& mesh, const MotionSpec& spec);

/// Classifies markers and boundary nodes, and checks everything about `spec`
/// against `mesh` that can fail: unknown marker names, node files (coverage,
/// ids, dimension), 2D motions out of the plane, moving nodes given a motion
/// or a new position that is not finite (a translation of 1.7e308), and the
/// shared-node rule in every frame of a frame list (for periodic motions, in
/// step 0).
/// Throws MeshError naming the marker (and node, when one node is at fault);
/// for an unknown marker, the message lists the mesh's markers.
ResolvedBoundary resolve_boundary(const Mesh& mesh, const MotionSpec& spec);

/// One frame's motion of the boundary nodes.
struct ResolvedFrame {
    BoundaryMotion motion;              // one NodeMotion per node of the BoundarySet, in its order
    std::vector<Warning> warnings;      // e.g. a marker moved farther than the mesh's size
    /// Boundary faces the motion itself turns over (a warning names them):
    /// no method keeps the cells on them valid, so callers skip work that
    /// cannot help (DG-harmonic's guard).
    std::int64_t folded_faces = 0;
};

/// The motion of every boundary node in frame `frame` (< frame_count(spec)).
/// `resolved` must be resolve_boundary(mesh, spec) for this mesh and spec.
/// Reads frame `frame` of `spec` only: its cost does not depend on the number
/// of frames (resolve it once, then call this for each frame of a series).
/// Throws MeshError as resolve_boundary does for this frame, and when moving
/// markers disagree on shared nodes in this frame (naming the pairs of
/// markers and the node counts).
ResolvedFrame resolve_frame(const Mesh& mesh, const MotionSpec& spec, const ResolvedBoundary& resolved,
                            std::size_t frame);

/// The warnings resolve_frame gives about large motions (a moving marker
/// turning by more than 180 degrees, or moving a node farther than the mesh's
/// bounding-box diagonal), for a `motion` of the boundary nodes given as it
/// is (one NodeMotion per node of resolved.boundary, e.g. arrays from Python)
/// rather than resolved from a motion spec; `at` says where, as "motion
/// (frame 3)" does.
std::vector<Warning> large_motion_warnings(const Mesh& mesh, const ResolvedBoundary& resolved,
                                           const BoundaryMotion& motion, const std::string& at);

/// resolve_boundary's warning about `count` boundary nodes on both a moving
/// and a static marker (what `rule` does with them); for a count over every
/// part of a decomposed mesh.
Warning shared_nodes_warning(std::int64_t count, SharedNodeRule rule);

/// The new positions of the boundary nodes under `motion` (apply_motion per
/// node): boundary.nodes.size() × mesh.dim, row-major, in BoundarySet order.
std::vector<double> moved_boundary_points(const Mesh& mesh, const BoundarySet& boundary,
                                          const BoundaryMotion& motion);

/// The displacement of every mesh node under `motion`: its new position
/// (moved_boundary_points) minus its position in `mesh` for the boundary
/// nodes, zero for the others: num_points × mesh.dim, row-major, in node
/// order. What a method must move the boundary by (exported for other
/// solvers: `dgwarp motion-field`).
std::vector<double> node_displacements(const Mesh& mesh, const BoundarySet& boundary, const BoundaryMotion& motion);

}  // namespace dgwarp
