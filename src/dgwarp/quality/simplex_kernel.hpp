#pragma once
// Internal to the quality module (quality_layout.cpp): Knupp's shape metric
// of triangles (2D) and tetrahedra over blocks of simplices whose edge
// vectors the caller has laid out column by column, so that the loops
// vectorise (DGWARP_SIMD_CLONES, -ffp-contract=off: every clone rounds each
// operation as the scalar code does). Each value is computed with the
// operations, in the order, of simplex_quality.cpp (on points that need no
// scaling: corner_jacobian.hpp's to_scaled_points leaves coordinates up to
// 2^400 as they are), so it is cell_shape_quality's to the bit.
#include <cstddef>

namespace dgwarp::quality_detail {

/// Simplices per block (the columns stay in L1).
constexpr std::size_t simplex_block = 256;

/// The edge vectors of up to simplex_block simplices from their first node,
/// column by column: 3D a1 = (e[0], e[1], e[2]), a2 = (e[3], e[4], e[5]),
/// a3 = (e[6], e[7], e[8]); 2D a1 = (e[0], e[1]), a2 = (e[2], e[3]).
/// `sign`: the orientation each simplex is judged against (+1 or -1).
struct SimplexBlock {
    double e[9][simplex_block];
    double sign[simplex_block];
};

/// Simplex i of `in`: α = a3 · (a1 × a2) (corner_jacobian) and the
/// denominator 1.5 tr λ - (λ12 + λ23 + λ13) of tetrahedron_quality, λ = AᵀA.
/// Inline, for the vectorised loops here and in DG-harmonic's guard.
inline void tetrahedron_alpha_and_denominator(const SimplexBlock& in, std::size_t i, double& alpha, double& den) {
    const double a1x = in.e[0][i], a1y = in.e[1][i], a1z = in.e[2][i];
    const double a2x = in.e[3][i], a2y = in.e[4][i], a2z = in.e[5][i];
    const double a3x = in.e[6][i], a3y = in.e[7][i], a3z = in.e[8][i];
    const double c0 = a1y * a2z - a1z * a2y;
    const double c1 = a1z * a2x - a1x * a2z;
    const double c2 = a1x * a2y - a1y * a2x;
    alpha = a3x * c0 + a3y * c1 + a3z * c2;
    const double l11 = a1x * a1x + a1y * a1y + a1z * a1z;
    const double l22 = a2x * a2x + a2y * a2y + a2z * a2z;
    const double l33 = a3x * a3x + a3y * a3y + a3z * a3z;
    const double l12 = a1x * a2x + a1y * a2y + a1z * a2z;
    const double l13 = a1x * a3x + a1y * a3y + a1z * a3z;
    const double l23 = a2x * a3x + a2y * a3y + a2z * a3z;
    den = 1.5 * (l11 + l22 + l33) - (l12 + l23 + l13);
}
/// Triangle i of a 2D block: α = (a1 × a2)_z and λ11 + λ22 - λ12 (triangle_quality on a plane).
inline void triangle_alpha_and_denominator(const SimplexBlock& in, std::size_t i, double& alpha, double& den) {
    const double a1x = in.e[0][i], a1y = in.e[1][i], a2x = in.e[2][i], a2y = in.e[3][i];
    alpha = a1x * a2y - a1y * a2x;
    den = (a1x * a1x + a1y * a1y) + (a2x * a2x + a2y * a2y) - (a1x * a2x + a1y * a2y);
}

/// The cube roots of `x[i]` for i < count, each std::cbrt's to the bit:
/// glibc's cbrt (its frexp, polynomial, one Newton step, factor and ldexp)
/// written out without its two calls, so that the loop vectorises; values
/// that are not positive normal numbers go to std::cbrt itself, and so does
/// everything when a check of the two on 16k values at start-up finds a
/// difference (another C library).
void cube_roots(const double* x, std::size_t count, double* root);
/// The cube root of one positive normal number by the same arithmetic (for the tests).
double glibc_cbrt_of_normal(double x);

/// For i < count: quality[i] as cell_shape_quality gives it (tetrahedra;
/// triangles of a 2D mesh).
void tetrahedron_qualities(const SimplexBlock& in, std::size_t count, double* quality);
void triangle_qualities(const SimplexBlock& in, std::size_t count, double* quality);

/// The same with alpha[i] = α as below too, in the same pass. Against
/// sign -1 a simplex's quality is minus its quality against +1, to the bit
/// (each operation is odd in the sign: the product, |v|, the cube root of
/// |v|, t and 3t / den; 0 stays +0), which lets one pass against +1 give
/// both the orientation and, once the orientation judged by is known, the
/// quality (tests/quality/quality_layout_test.cpp).
void tetrahedron_qualities_and_alphas(const SimplexBlock& in, std::size_t count, double* quality, double* alpha);
void triangle_qualities_and_alphas(const SimplexBlock& in, std::size_t count, double* quality, double* alpha);

/// For i < count: alpha[i] = α (six times the signed volume, twice the signed
/// area), `sign` not applied: cell_orientation is -1 where it is negative.
void tetrahedron_alphas(const SimplexBlock& in, std::size_t count, double* alpha);
void triangle_alphas(const SimplexBlock& in, std::size_t count, double* alpha);

}  // namespace dgwarp::quality_detail
