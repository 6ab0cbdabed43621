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

}  // namespace dgwarp
