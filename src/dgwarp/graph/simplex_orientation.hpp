#pragma once
// Validity of a moved Delaunay graph (DGM, METHODS.md): every simplex must
// keep a positive signed area / volume. The sign is judged with CGAL's exact
// orientation predicate, so a thin but valid simplex is classified correctly.
//
// One exemption: a simplex that is flat to round-off both before and after the
// move. Such slivers appear when a graph is built on boundary points that are
// coplanar (collinear in 2D) in exact arithmetic but were rounded, e.g. the
// faces of a rotated box: the Delaunay graph of the rounded points may hold a
// simplex of volume ~1e-16 relative to its size, whose sign after any motion
// is round-off, not a fold. "Flat to round-off" means |det| <= tau with
//   tau = 16 dim u (X + l) l^(dim-1),
// det = dim! × the signed measure, u = 2^-53 (unit round-off), l the longest
// edge and X the largest absolute coordinate of the simplex: a bound on how
// much rounding the vertex coordinates and the determinant can change det.
#include <cstdint>
#include <span>
#include <vector>

namespace dgwarp {

/// Per simplex, 1 when the move from `from` to `to` leaves it invalid, else 0:
/// its orientation at `to` is not positive, unless it is flat to round-off at
/// both (see above).
///  dim:        2 or 3
///  simplices:  num_simplices × (dim + 1) vertex ids (rows of a DelaunayGraph,
///              positively oriented at `from` unless flat to round-off there)
///  from, to:   num_vertices × dim vertex coordinates before and after, row-major
/// Threaded; the result does not depend on the thread count.
std::vector<std::uint8_t> invalid_moved_simplices(int dim, std::span<const std::int32_t> simplices,
                                                  std::span<const double> from, std::span<const double> to);

/// The number of simplices invalid_moved_simplices flags.
std::int64_t count_invalid_moved_simplices(int dim, std::span<const std::int32_t> simplices,
                                           std::span<const double> from, std::span<const double> to);

}  // namespace dgwarp
