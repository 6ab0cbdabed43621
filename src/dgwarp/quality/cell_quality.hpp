#pragma once
// Knupp's shape metric per element (P. M. Knupp, "Algebraic mesh quality
// metrics", SIAM J. Sci. Comput. 23(1), 2001), the quality measure of the
// DG-IDW paper (its reference [24]). Pure functions that never throw.
// Definitions, signs and the prism/pyramid extension: docs/QUALITY.md (repository root).
#include <span>

#include "dgwarp/mesh/cell_type.hpp"

namespace dgwarp {

/// Shape quality of one element: 1 for the ideal element (equilateral
/// triangle, square, regular tetrahedron, cube, right prism on an equilateral
/// triangle with height equal to its edge, pyramid with all 8 edges equal),
/// 0 for a degenerate one, <= 0 when inverted relative to `orientation`
/// (+1: the element's reference orientation is its node order's; -1: the
/// reference element was mirrored, e.g. a 2D mesh written clockwise).
/// Invariant under translation, rotation and uniform scaling.
///
/// `coords`: nodes_per_cell(type) × dim, row-major, nodes in VTK order.
/// `dim`: 2 for triangles and quadrilaterals of a 2D mesh, else 3. Triangles
/// and quadrilaterals given with dim 3 (faces in space) have no orientation:
/// `orientation` is ignored, triangles score >= 0 (α = |cross product|) and a
/// quadrilateral's corners are signed along its mean normal.
/// Simplices are signed by orientation × α; corner-based elements score the
/// harmonic mean of their corner qualities when every corner is positive,
/// otherwise the worst corner's signed value (<= 0).
/// Returns 0 for vertex and line. Never NaN for finite coordinates.
double cell_shape_quality(CellType type, std::span<const double> coords, int dim, int orientation = 1);

/// The orientation of an element as written: +1 when its signed measure (α
/// for simplices: twice the area, six times the volume; for the other types
/// the sum of their corner Jacobian determinants, as used by
/// cell_shape_quality) is positive or zero, -1 when negative. +1 for vertex,
/// line, and for triangles and quadrilaterals with dim 3.
/// `coords`: nodes_per_cell(type) × dim, row-major, VTK node order.
int cell_orientation(CellType type, std::span<const double> coords, int dim);

}  // namespace dgwarp
