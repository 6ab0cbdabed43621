// deform_dg_harmonic: one harmonic solve on the coarse graph, then one pass over the nodes.
#include <algorithm>
#include <cmath>
#include <cstring>
#include <type_traits>
#include <vector>

#include "dgwarp/core/parallel_for.hpp"
#include "dgwarp/core/prefetch.hpp"
#include "dgwarp/core/progress.hpp"
#include "dgwarp/core/step_kernel.hpp"
#include "dgwarp/methods/boundary_mover.hpp"
#include "dgwarp/methods/dg_harmonic.hpp"
#include "dgwarp/methods/dg_harmonic_solve.hpp"
#include "dgwarp/methods/dg_harmonic_step.hpp"
#include "dgwarp/methods/method_inputs.hpp"
#include "dgwarp/methods/rotation_series.hpp"

namespace dgwarp {

namespace {

constexpr std::int64_t deform_block = 16384;

// Values carried per coarse vertex: t (Dim), w (W: 1 in 2D, 3 in 3D), the
// angle |w| and |w| c (Dim). The centre of a node is (|w| c) / |w|.
template <int Dim>
struct Layout {
    static constexpr int W = Dim == 2 ? 1 : 3;
    static constexpr int t = 0, w = Dim, angle = Dim + W, wc = Dim + W + 1;
    static constexpr int size = 2 * Dim + W + 1;
};

// Whether any boundary vertex translates, rotates.
struct Active {
    bool translation = false, rotation = false;
};

// The values of the boundary vertices (num_boundary_vertices × size).
template <int Dim>
Active boundary_values(const DgHarmonicPlan& plan, const BoundaryMotion& motion, double* g) {
    using L = Layout<Dim>;
    Active active;
    for (std::int32_t v = 0; v < plan.num_boundary_vertices; ++v) {
        double* x = g + static_cast<std::size_t>(v) * L::size;
        std::fill(x, x + L::size, 0.0);
        const std::int32_t b = plan.vertex_motion[v];
        if (b < 0) continue;
        const NodeMotion& m = motion[b];
        for (int d = 0; d < Dim; ++d) x[L::t + d] = m.translation[d];
        for (int j = 0; j < L::W; ++j) x[L::w + j] = m.rotation[3 - L::W + j];
        double a2 = 0;
        for (int j = 0; j < L::W; ++j) a2 += x[L::w + j] * x[L::w + j];
        const double angle = std::sqrt(a2);
        x[L::angle] = angle;
        for (int d = 0; d < Dim; ++d) x[L::wc + d] = angle * m.center[d];
        for (int d = 0; d < Dim; ++d) active.translation |= x[L::t + d] != 0;
        active.rotation |= angle != 0;
    }
    return active;
}

using harmonic_detail::solve_interior;

// solve_interior for components [Offset, Offset + C), on two threads when
// there are two: each solves half of the components (its own pass over the
// factor). A component's operations do not depend on which others are solved
// with it, so the bits are those of one solve for all, whatever the thread
// count. The substitutions are one chain through the factor (about 8 ms of a
// 26 ms step at 865k nodes, one thread): on one thread beside a halved
// per-node pass, they held two threads to 1.4-1.5x.
template <int K, int Offset, int C>
void solve_interior_split(const HarmonicFactors& f, const HarmonicFactors::System& sys, std::int32_t first_unknown,
                          double* values) {
    if constexpr (C >= 2) {
        if (num_threads() >= 2) {
            constexpr int Half = C / 2;
            run_concurrently([&] { solve_interior<K, Offset, Half>(f, sys, first_unknown, values); },
                             [&] { solve_interior<K, Offset + Half, C - Half>(f, sys, first_unknown, values); });
            return;
        }
    }
    solve_interior<K, Offset, C>(f, sys, first_unknown, values);
}

// The per-node pass, compiled twice (core/step_kernel.hpp).
#define DGWARP_STEP_KERNEL "dgwarp/methods/dg_harmonic_step_kernel.inc"
#include "dgwarp/core/step_kernel_copies.inc"

template <int Dim>
void run(const DgHarmonicPlan& plan, std::span<const double> points, const BoundaryMotion& motion,
         std::span<double> out, StepKernel kernel, const ProgressFn& progress) {
    constexpr int K = Layout<Dim>::size;
    std::vector<double> values(static_cast<std::size_t>(plan.num_vertices()) * K);
    using L = Layout<Dim>;
    const Active active = boundary_values<Dim>(plan, motion, values.data());
    // A system whose data are all zero has the solution 0 (values start at 0).
    const HarmonicFactors& f = plan.solve;
    const std::int32_t nb = plan.num_boundary_vertices;
    const HarmonicFactors::System& rotation = f.shared ? f.translation : f.rotation;
    if (f.shared && active.translation && active.rotation) {
        solve_interior_split<K, 0, K>(f, f.translation, nb, values.data());  // one factor for all
    } else if (active.translation && active.rotation && num_threads() >= 2) {
        run_concurrently([&] { solve_interior<K, L::t, Dim>(f, f.translation, nb, values.data()); },
                         [&] { solve_interior<K, L::w, K - Dim>(f, rotation, nb, values.data()); });
    } else {
        if (active.translation) solve_interior_split<K, L::t, Dim>(f, f.translation, nb, values.data());
        if (active.rotation) solve_interior_split<K, L::w, K - Dim>(f, rotation, nb, values.data());
    }
    [[maybe_unused]] const bool avx2 = kernel == StepKernel::automatic && cpu_has_avx2();
    ProgressCounter moved(progress, plan.num_points());  // the pass: the solve above is the small part
    parallel_for_blocks(plan.num_points(), deform_block, [&](std::int64_t begin, std::int64_t end) {
        auto pass = [&]<bool Rotates>() {
#if defined(__x86_64__)
            if (avx2) {
                return avx2::deform_range<Dim, Rotates, Isa::avx2>(plan, points.data(), motion.data(), values.data(),
                                                                   out.data(), begin, end);
            }
#endif
            sse2::deform_range<Dim, Rotates, Isa::sse2>(plan, points.data(), motion.data(), values.data(),
                                                       out.data(), begin, end);
        };
        if (active.rotation) pass.template operator()<true>();
        else pass.template operator()<false>();
        moved.add(end - begin);
    });
    moved.finish();
}

}  // namespace

DgHarmonicStepReport deform_dg_harmonic(const DgHarmonicPlan& plan, std::span<const double> points,
                                        const BoundaryMotion& motion, std::span<double> out,
                                        const ProgressFn& progress) {
    return deform_dg_harmonic_with(plan, points, motion, out, StepKernel::automatic, progress);
}

DgHarmonicStepReport deform_dg_harmonic_with(const DgHarmonicPlan& plan, std::span<const double> points,
                                             const BoundaryMotion& motion, std::span<double> out, StepKernel kernel,
                                             const ProgressFn& progress) {
    check_step_arrays("DG-harmonic", plan.num_points(), plan.dim, plan.boundary_nodes, points, motion, out);
    if (plan.dim == 2) run<2>(plan, points, motion, out, kernel, progress);
    else run<3>(plan, points, motion, out, kernel, progress);
    return {conflicting_shared_vertices(plan, motion)};
}

}  // namespace dgwarp
