#pragma once
// Internal to DG-harmonic: its two coarse Laplacians (translation and
// rotation), factorised once at prepare time. The stiffness weights are the
// P1 ones with negative sums set to 0 (the discrete maximum principle), so an
// unknown whose every edge weight became 0 (3D slivers all round) would give
// a zero pivot: the factorisation checks every pivot and, where one is not
// positive, floors the weights (floor_weights) and factorises again.
#include <cstdint>
#include <span>
#include <utility>
#include <vector>

#include "dgwarp/methods/dg_harmonic.hpp"

namespace dgwarp {

/// Whether every pivot `d` of an LDL^T factor is positive and finite and at
/// least `relative` × the largest: a symmetric positive definite matrix's
/// factor, numerically.
bool pivots_positive(std::span<const double> d, double relative = 1e-13);

/// `weights` with every weight below `fraction` × their mean positive weight
/// (1 when none is positive) raised to it; `floored` (when not null) gets how
/// many were raised. The Laplacian of a connected graph with Dirichlet
/// vertices and positive weights is positive definite.
std::vector<double> floor_weights(std::span<const double> weights, double fraction = 1e-6,
                                  std::int64_t* floored = nullptr);

/// Assembles the Laplacians of the coarse graph with the two weights per
/// edge and factorises their unknown blocks: one ordering and symbolic
/// analysis, two numeric factorisations. `edges`: (u, v), u < v, every edge
/// touching an unknown (vertices first_unknown .. first_unknown +
/// num_unknowns - 1; the others are boundary vertices, Dirichlet). A system
/// whose factor fails pivots_positive is factorised again with
/// floor_weights; `floored` (when not null) gets the weights raised (both
/// systems). Throws Error when even that fails (a block of unknowns with no
/// edge to the boundary: not a coarse graph).
HarmonicFactors factorise_coarse_laplacian(std::span<const std::pair<std::int32_t, std::int32_t>> edges,
                                           std::span<const double> translation_weight,
                                           std::span<const double> rotation_weight, std::int32_t first_unknown,
                                           std::int32_t num_unknowns, std::int64_t* floored = nullptr);

}  // namespace dgwarp
