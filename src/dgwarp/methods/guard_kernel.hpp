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

namespace dgwarp::guard_detail {

/// Simplices per block of the kernel (its columns stay in L1).
constexpr std::size_t kernel_block = 256;

/// The edge vectors of up to kernel_block simplices from their first node,
/// column by column: 3D a1 = (e[0], e[1], e[2]), a2 = (e[3], e[4], e[5]),
/// a3 = (e[6], e[7], e[8]); 2D a1 = (e[0], e[1]), a2 = (e[2], e[3]). `sign`:
/// the orientation each simplex is judged against (+1 or -1).
struct SimplexEdges {
    double e[9][kernel_block];
    double sign[kernel_block];
};

/// For i < count: alpha[i] = sign × α (six times the signed volume, twice the
/// signed area) and key[i] the guard's key of a plainly valid simplex
/// (tetrahedra: q^3 = 54 r^2 / den with r = α / den; triangles: q = sqrt 3 α /
/// den), or NaN when the simplex is not plainly valid (α or den not positive,
/// or a key that is not finite and positive): the caller computes those
/// exactly.
void tetrahedron_keys(const SimplexEdges& in, std::size_t count, double* alpha, double* key);
void triangle_keys(const SimplexEdges& in, std::size_t count, double* alpha, double* key);

}  // namespace dgwarp::guard_detail
