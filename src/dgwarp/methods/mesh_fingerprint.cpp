#include "dgwarp/methods/mesh_fingerprint.hpp"

#include <string>

#include "dgwarp/core/error.hpp"
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

void check_fingerprint(const MeshFingerprint& made_for, int dim, std::size_t plan_boundary_nodes,
                       std::span<const double> points, const BoundarySet& boundary) {
    const MeshFingerprint f = mesh_fingerprint(dim, points, boundary);
    // What to do about it, for every mismatch: a plan cannot be adapted.
    const std::string again = "; prepare the plan again for this mesh and motion (dgwarp prepare, dgwarp.prepare)";
    if (f.num_points != made_for.num_points)
        throw MeshError("the plan was made for another mesh (" + std::to_string(made_for.num_points) +
                        " points vs " + std::to_string(f.num_points) + " in this mesh)" + again);
    if (f.points_hash != made_for.points_hash)
        throw MeshError("the plan was made for another mesh: same number of points (" +
                        std::to_string(f.num_points) + ") but different coordinates" + again);
    if (f.boundary_hash != made_for.boundary_hash) {
        const std::size_t n = boundary.nodes.size();
        throw MeshError("the plan was made for another boundary: same mesh, but " +
                        (plan_boundary_nodes == n
                             ? "the same number of boundary nodes (" + std::to_string(n) +
                                   ") with other nodes or other moving markers (another motion's)"
                             : "other boundary nodes (" + std::to_string(plan_boundary_nodes) + " vs " +
                                   std::to_string(n) + " here)") +
                        again);
    }
}

}  // namespace dgwarp
