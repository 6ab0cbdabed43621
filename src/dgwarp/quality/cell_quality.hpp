#pragma once
// Knupp's shape metric per element (P. M. Knupp, "Algebraic mesh quality
// metrics", SIAM J. Sci. Comput. 23(1), 2001), the quality measure of the
// DG-IDW paper (its reference [24]). Pure functions that never throw.
// Definitions, signs and the prism/pyramid extension: ../../docs/QUALITY.md.
#include <span>

#include "dgwarp/mesh/cell_type.hpp"

namespace dgwarp {

/// Shape quality of one element: 1 for the ideal element, 0 for a degenerate
/// one, <= 0 when inverted relative to `orientation` (+1: the element's
/// reference orientation is its node order's; -1: the reference element was
/// mirrored, e.g. a 2D mesh written clockwise).
/// `coords`: nodes_per_cell(type) × dim, row-major (dim 2 for triangles and
/// quadrilaterals of a 2D mesh, 3 otherwise). Returns 0 for vertex and line.
double cell_shape_quality(CellType type, std::span<const double> coords, int dim, int orientation = 1);

/// The orientation of an element as written: +1 when its signed measure (area,
/// volume; for non-simplices the sum of its corner Jacobian determinants) is
/// positive or zero, -1 when negative.
int cell_orientation(CellType type, std::span<const double> coords, int dim);

}  // namespace dgwarp
