#pragma once
// The faces of a polyhedron as files give them, turned to point out of it:
// VTK's polyhedra may list their faces in any orientation (VTK's own example
// files mix them), and the neutral Mesh keeps them outward (mesh.hpp).
#include <optional>
#include <span>
#include <string>

#include "dgwarp/mesh/mesh.hpp"

namespace dgwarp {

/// Turns the faces of one polyhedron (face_sizes.size() rings, one after
/// another in `rings`, node ids into `points`, num_points × 3) so that every
/// face's normal (right-hand rule) points out of it: first consistently (two
/// faces that share an edge run it in opposite directions, found face by
/// face from the first), then all of them once more when the volume they
/// enclose (from the face and node centres) is negative. Returns why it
/// cannot, naming the edge, when an edge is not shared by exactly two faces
/// (the faces do not close a polyhedron); nullopt when done.
std::optional<std::string> orient_polyhedron_faces(std::span<NodeId> rings, std::span<const int> face_sizes,
                                                   std::span<const double> points);

}  // namespace dgwarp
