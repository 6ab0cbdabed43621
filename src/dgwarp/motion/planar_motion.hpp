#pragma once
// A motion of a 2D case stored as 3D (mesh/planar_case.hpp) as a motion of
// its 2D mesh: every marker motion in the planes' coordinates. A 2D case moves
// in its planes: a translation or displacement along the normal, or a
// rotation about another axis than the normal, is an error naming the marker.
#include "dgwarp/mesh/planar_case.hpp"
#include "dgwarp/motion/motion_spec.hpp"

namespace dgwarp {

/// `spec`, a motion of the 3D mesh `mesh` whose planar case is `planar`, as a
/// motion of planar.mesh: rigid and periodic motions about the normal (their
/// centres in 2D coordinates), translations and displacements in 2D
/// components, positions in 2D coordinates; a node table's 3D node ids as the
/// 2D nodes they are (a node and its twin may both be given, alike within
/// 1e-9 of the mesh's size). The plane markers are left out (they must slide:
/// SlideMotion or not named). Throws MeshError naming the marker (and node).
MotionSpec planar_motion(const PlanarCase& planar, const Mesh& mesh, const MotionSpec& spec);

}  // namespace dgwarp
