// Plan bookkeeping: its size and the check that it fits a mesh.
#include <string>

#include "dgwarp/core/error.hpp"
#include "dgwarp/methods/dg_idw.hpp"
#include "dgwarp/methods/method_inputs.hpp"

namespace dgwarp {

std::size_t plan_bytes(const DgIdwPlan& plan) {
    return sizeof(DgIdwPlan) + core_bytes(plan) + bytes_of(plan.simplex_motion) + bytes_of(plan.node_coefficients);
}

void check_plan_fits(const DgIdwPlan& plan, std::span<const double> points, const BoundarySet& boundary) {
    check_fingerprint(plan.mesh, plan.dim, plan.boundary_nodes.size(), points, boundary);
}

}  // namespace dgwarp
