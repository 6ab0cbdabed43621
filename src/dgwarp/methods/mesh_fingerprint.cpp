#include "dgwarp/methods/mesh_fingerprint.hpp"

#include "dgwarp/core/hash.hpp"

namespace dgwarp {

MeshFingerprint mesh_fingerprint(int dim, std::span<const double> points, const BoundarySet& boundary) {
    MeshFingerprint f;
    f.num_points = static_cast<std::int64_t>(points.size()) / dim;
    f.points_hash = hash64_of(points);
    f.boundary_hash = hash64_of(std::span<const NodeId>(boundary.nodes),
                                hash64_of(std::span<const std::uint8_t>(boundary.moving)));
    return f;
}

}  // namespace dgwarp
