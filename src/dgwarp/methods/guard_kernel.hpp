#pragma once
// Internal to DG-harmonic's guard (dg_harmonic_guard.cpp): the arithmetic of
// its measure, over blocks of simplices whose edge vectors the caller has
// laid out column by column, so that the loops vectorise
// (DGWARP_SIMD_CLONES: AVX-512, AVX2 or SSE2, the same bits in each,
// -ffp-contract=off). Each value is computed with the operations, in the
// order, of quality/simplex_quality.cpp. (Reading the points inside the
// vector loop, by gathers, measured slower: GCC emulates the gathers, and
// the loop spills registers.)
#include <cstddef>

#include "dgwarp/quality/simplex_kernel.hpp"

namespace dgwarp::guard_detail {

/// Simplices per block of the kernel (its columns stay in L1).
constexpr std::size_t kernel_block = quality_detail::simplex_block;

/// The edge vectors of up to kernel_block simplices from their first node,
/// column by column, and the orientation each is judged against: the quality
/// pass's block (quality/simplex_kernel.hpp).
using SimplexEdges = quality_detail::SimplexBlock;

/// For i < count: alpha[i] = sign × α (six times the signed volume, twice the
/// signed area) and key[i] the guard's key of a plainly valid simplex
/// (tetrahedra: q^3 = 54 r^2 / den with r = α / den; triangles: q = sqrt 3 α /
/// den), or NaN when the simplex is not plainly valid (α or den not positive,
/// or a key that is not finite and positive): the caller computes those
/// exactly.
void tetrahedron_keys(const SimplexEdges& in, std::size_t count, double* alpha, double* key);
void triangle_keys(const SimplexEdges& in, std::size_t count, double* alpha, double* key);

}  // namespace dgwarp::guard_detail
