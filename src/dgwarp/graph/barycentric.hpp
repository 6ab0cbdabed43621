#pragma once
// Barycentric (area / volume ratio) coordinates of a point in a simplex.
namespace dgwarp {

/// Barycentric coordinates of the point x (dim coordinates) in the simplex
/// with corners corner[0..dim] (each dim coordinates,
/// dim 2 or 3): e[k] = measure of the simplex with corner k replaced by x,
/// over their sum (the DGM paper's area / volume ratios). e sums to 1 and
/// x = sum_k e_k corner_k up to round-off; e_k < 0 when x is on the far side
/// of the face opposite corner k. Corners are taken relative to x, which keeps
/// the sub-measures accurate for a small simplex far from the origin.
/// A degenerate simplex (measure within 1e-12 of its edges' scale^dim of 0:
/// corners on a plane or a line, as the Delaunay graph of points on a lattice
/// has them, with x on it) gets x's coordinates in the facet or edge holding it
/// best, the other corners 0: finite, summing to 1 (the ratios would be 0/0).
void barycentric(int dim, const double* x, const double* const* corner, double* e);

}  // namespace dgwarp
