// deform_dg_idw: one pass over the nodes per step.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstring>
#include <sstream>
#include <string>
#include <type_traits>

#include "dgwarp/core/error.hpp"
#include "dgwarp/core/parallel_for.hpp"
#include "dgwarp/core/prefetch.hpp"
#include "dgwarp/core/progress.hpp"
#include "dgwarp/core/step_kernel.hpp"
#include "dgwarp/methods/method_inputs.hpp"
#include "dgwarp/methods/boundary_mover.hpp"
#include "dgwarp/methods/dg_idw.hpp"
#include "dgwarp/methods/dg_idw_checks.hpp"
#include "dgwarp/methods/dg_idw_step.hpp"
#include "dgwarp/methods/rotation_series.hpp"

namespace dgwarp {

namespace {

// Nodes per block of the threaded loop: large enough that handing out a block
// costs nothing against it, small enough (~50 blocks at 800k nodes) to balance.
constexpr std::int64_t deform_block = 16384;

// Per-step constants: sigma = 1 / (1 + rho * k) with k = 1 / (a L) (dg_idw.hpp).
struct StepConstants {
    double k_t;  // 1 / (a_translation L)
    double k_r;  // 1 / (a_rotation L)
};


// The rotation factors with a series of Terms terms; 10: any angle.
template <int Terms>
RotationFactors factors(double angle2) {
    if constexpr (Terms >= 10) {
        return rotation_factors(angle2);
    } else {
        return rotation_factors_series<Terms>(angle2);
    }
}

// The per-node kernel, compiled twice (core/step_kernel.hpp).
#define DGWARP_STEP_KERNEL "dgwarp/methods/dg_idw_step_kernel.inc"
#include "dgwarp/core/step_kernel_copies.inc"

}  // namespace

void check_dg_idw_options(const DgIdwOptions& options) {
    auto in_range = [](double a) { return a >= dg_idw_a_min && a <= dg_idw_a_max; };  // false for NaN
    if (!in_range(options.a_translation) || !in_range(options.a_rotation)) {
        std::ostringstream e;
        e << "DG-IDW: a_translation and a_rotation must be in [" << dg_idw_a_min << ", " << dg_idw_a_max << "], got "
          << options.a_translation << " and " << options.a_rotation;
        throw Error(e.str());
    }
    if (!std::isfinite(options.length_scale) || options.length_scale < 0)
        throw Error("DG-IDW: length_scale must be finite and >= 0 (0 = auto), got " +
                    std::to_string(options.length_scale));
    if (options.weighting != DgIdwWeighting::paper && options.weighting != DgIdwWeighting::continuous)
        throw Error("DG-IDW: unknown weighting " + std::to_string(static_cast<int>(options.weighting)));
}

DgIdwStepReport deform_dg_idw(const DgIdwPlan& plan, std::span<const double> points,
                              const BoundaryMotion& motion, std::span<double> out, const ProgressFn& progress) {
    return deform_dg_idw_bounded(plan, points, motion, out, max_rotation_angle2(plan, motion), StepKernel::automatic,
                                 progress);
}

double max_rotation_angle2(const DgIdwPlan& plan, const BoundaryMotion& motion) {
    double angle2_max = 0;
    for (std::size_t b = 0; b < motion.size() && b < plan.boundary_moving.size(); ++b) {
        if (!plan.boundary_moving[b]) continue;
        const Vec3& w = motion[b].rotation;
        angle2_max = std::max(angle2_max, plan.dim == 2 ? w[2] * w[2] : w[0] * w[0] + w[1] * w[1] + w[2] * w[2]);
    }
    return angle2_max;
}

DgIdwStepReport deform_dg_idw_bounded(const DgIdwPlan& plan, std::span<const double> points,
                                      const BoundaryMotion& motion, std::span<double> out, double angle2_max,
                                      StepKernel kernel, const ProgressFn& progress) {
    const DgIdwOptions& options = plan.options;
    check_dg_idw_options(options);
    check_step_arrays("DG-IDW", plan.num_points(), plan.dim, plan.boundary_nodes, points, motion, out);
    const double l = options.length_scale > 0 ? options.length_scale : plan.auto_length_scale;
    const StepConstants sc{1.0 / (options.a_translation * l), 1.0 / (options.a_rotation * l)};
    // The interpolated rotation vector is a combination of the moving nodes'
    // ones with non-negative weights summing to at most 1, so its angle is at
    // most their largest: that bounds the Taylor terms the step needs.
    const int terms = angle2_max == 0                           ? 0
                      : angle2_max <= taylor_angle2_limit(4) ? 4
                      : angle2_max <= taylor_angle2_limit(6) ? 6
                      : angle2_max <= taylor_angle2_limit(8) ? 8
                                                               : 10;

    [[maybe_unused]] const bool avx2 = kernel == StepKernel::automatic && cpu_has_avx2();
    ProgressCounter moved(progress, plan.num_points());
    auto run = [&]<int Dim, int Terms>() {
        // Blocks handed out as threads free up: the cost per node varies along
        // the node order (boundary nodes, simplices with 0 to 4 moving corners).
        parallel_for_blocks(plan.num_points(), deform_block, [&](std::int64_t begin, std::int64_t end) {
#if defined(__x86_64__)
            if constexpr (Dim == 3) {
                if (avx2) {
                    avx2::deform_range<3, Terms, Isa::avx2>(plan, points.data(), motion.data(), out.data(), sc, begin,
                                                            end);
                    moved.add(end - begin);
                    return;
                }
            }
#endif
            sse2::deform_range<Dim, Terms, Isa::sse2>(plan, points.data(), motion.data(), out.data(), sc, begin, end);
            moved.add(end - begin);
        });
    };
    auto run_dim = [&]<int Dim>() {
        switch (terms) {
            case 0: return run.template operator()<Dim, 0>();
            case 4: return run.template operator()<Dim, 4>();
            case 6: return run.template operator()<Dim, 6>();
            case 8: return run.template operator()<Dim, 8>();
            default: return run.template operator()<Dim, 10>();
        }
    };
    if (plan.dim == 2) run_dim.template operator()<2>();
    else run_dim.template operator()<3>();
    moved.finish();
    return {conflicting_shared_vertices(plan, motion)};
}

}  // namespace dgwarp
