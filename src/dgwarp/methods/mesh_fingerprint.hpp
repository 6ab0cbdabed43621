#pragma once
// A fingerprint of the mesh and boundary set a plan is built for, so a plan
// is never applied to another mesh by mistake.
#include <cstdint>
#include <span>

#include "dgwarp/motion/node_motion.hpp"

namespace dgwarp {

struct MeshFingerprint {
    std::int64_t num_points = 0;
    std::uint64_t points_hash = 0;    // hash64 of the original coordinates (num_points × dim doubles)
    std::uint64_t boundary_hash = 0;  // hash64 of the boundary node ids and moving flags

    bool operator==(const MeshFingerprint&) const = default;
};

/// The fingerprint of `points` (num_points × dim, row-major) and `boundary`.
MeshFingerprint mesh_fingerprint(int dim, std::span<const double> points, const BoundarySet& boundary);

/// Throws MeshError when a plan made for `made_for` (dim-D, with
/// `plan_boundary_nodes` boundary nodes) does not fit these points and
/// boundary set ("the plan was made for another mesh (N points vs M)", the
/// same count with other coordinates, or another boundary set).
void check_fingerprint(const MeshFingerprint& made_for, int dim, std::size_t plan_boundary_nodes,
                       std::span<const double> points, const BoundarySet& boundary);

}  // namespace dgwarp
