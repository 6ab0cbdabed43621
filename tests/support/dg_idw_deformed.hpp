#pragma once
// The points a DG-IDW plan deforms, for the DG-IDW tests.
#include <cmath>
#include <vector>

#include "dgwarp/methods/dg_idw.hpp"

namespace dgwarp::test {

/// `points` deformed by `plan` (with the plan's options) and `motion`; NaN
/// wherever the step wrote nothing.
inline std::vector<double> dg_idw_deformed(const DgIdwPlan& plan, const std::vector<double>& points,
                                           const BoundaryMotion& motion) {
    std::vector<double> out(points.size(), std::nan(""));
    deform_dg_idw(plan, points, motion, out);
    return out;
}

}  // namespace dgwarp::test
