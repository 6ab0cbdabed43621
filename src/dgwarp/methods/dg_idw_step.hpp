#pragma once
// Internal: deform_dg_idw's step with the bound on the rotation angle given.
// The bound chooses how many Taylor terms the rotation factors take
// (rotation_series.hpp), so it changes the last bits of the result. The
// distributed step (dgwarp/mpi) holds only the motions its own nodes need and
// passes the bound of the whole boundary (a max reduced over the processes),
// so that its bits are the single-process run's.
#include <span>

#include "dgwarp/core/step_kernel.hpp"
#include "dgwarp/methods/dg_idw.hpp"

namespace dgwarp {

/// The largest squared rotation angle |w|^2 of the moving boundary nodes'
/// motions (in 2D, w_z^2).
double max_rotation_angle2(const DgIdwPlan& plan, const BoundaryMotion& motion);

/// deform_dg_idw, with angle2_max (>= max_rotation_angle2 of the motions the
/// nodes read) in place of the one computed from `motion`.
DgIdwStepReport deform_dg_idw_bounded(const DgIdwPlan& plan, std::span<const double> points,
                                      const BoundaryMotion& motion, std::span<double> out, double angle2_max,
                                      StepKernel kernel = StepKernel::automatic,  // core/step_kernel.hpp
                                      const ProgressFn& progress = {});

}  // namespace dgwarp
