#pragma once
// Knupp's shape metric per element (P. M. Knupp, "Algebraic mesh quality
// metrics", SIAM J. Sci. Comput. 23(1), 2001), the quality measure of the
// DG-IDW paper (its reference [24]). Pure functions that never throw.
// Definitions, signs and the prism/pyramid extension: docs/QUALITY.md (repository root).
#include <span>

#include "dgwarp/mesh/mesh.hpp"

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

/// cell_shape_quality of element i of `list` at `points` (num_points × dim),
/// for every type: polygons and polyhedra too, measured by their
/// decomposition from centres (docs/QUALITY.md): a polygon's triangles
/// (centre, corner k, corner k+1), a polyhedron's tetrahedra (face centre,
/// an edge of the face, cell centre; centres the mean of the nodes), each
/// against the same piece of the regular polygon with that many sides (of
/// the right prism on it, as high as the polygon's apothem), combined as the
/// corners of a hexahedron are. A regular polygon and a cube score 1; an
/// inverted piece makes the element <= 0 (a polyhedron is valid when each
/// of its tetrahedra is, as checkMesh's face pyramids).
double element_shape_quality(const ElementList& list, std::size_t i, int dim, std::span<const double> points,
                             int orientation = 1);

/// cell_orientation of element i of `list`: for a polygon in 2D the sign of
/// its pieces' summed α (twice its area), for a polyhedron of its
/// tetrahedra's (six times its volume from the centres).
int element_orientation(const ElementList& list, std::size_t i, int dim, std::span<const double> points);

}  // namespace dgwarp
