// Plan bookkeeping: its size and the check that it fits a mesh.
#include <string>

#include "dgwarp/core/error.hpp"
#include "dgwarp/methods/dg_idw.hpp"

namespace dgwarp {

namespace {
template <class T>
std::size_t bytes_of(const std::vector<T>& v) {
    return v.size() * sizeof(T);
}
}  // namespace

std::size_t plan_bytes(const DgIdwPlan& plan) {
    return sizeof(DgIdwPlan) + bytes_of(plan.boundary_nodes) + bytes_of(plan.boundary_moving) +
           bytes_of(plan.simplex_motion) + bytes_of(plan.shared_offsets) +
           bytes_of(plan.shared_members) + bytes_of(plan.node_simplex) + bytes_of(plan.node_coefficients);
}

void check_plan_fits(const DgIdwPlan& plan, std::span<const double> points, const BoundarySet& boundary) {
    const MeshFingerprint f = mesh_fingerprint(plan.dim, points, boundary);
    if (f.num_points != plan.mesh.num_points)
        throw MeshError("the plan was made for another mesh (" + std::to_string(plan.mesh.num_points) +
                        " points vs " + std::to_string(f.num_points) + " in this mesh)");
    if (f.points_hash != plan.mesh.points_hash)
        throw MeshError("the plan was made for another mesh: same number of points (" +
                        std::to_string(f.num_points) + ") but different coordinates");
    if (f.boundary_hash != plan.mesh.boundary_hash)
        throw MeshError("the plan was made for another boundary set: same mesh, but different boundary nodes "
                        "or moving flags (" + std::to_string(plan.boundary_nodes.size()) + " boundary nodes vs " +
                        std::to_string(boundary.nodes.size()) + ")");
}

}  // namespace dgwarp
