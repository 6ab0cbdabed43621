#pragma once
// Internal: deform_dg_harmonic with the compiled copy of its per-node pass
// chosen (StepKernel, core/step_kernel.hpp), for the test that both copies give
// the same bits.
#include <span>

#include "dgwarp/methods/dg_harmonic.hpp"
#include "dgwarp/core/step_kernel.hpp"

namespace dgwarp {

DgHarmonicStepReport deform_dg_harmonic_with(const DgHarmonicPlan& plan, std::span<const double> points,
                                             const BoundaryMotion& motion, std::span<double> out, StepKernel kernel,
                                             const ProgressFn& progress = {});

}  // namespace dgwarp
