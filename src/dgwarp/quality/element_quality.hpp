#pragma once
// Internal to the quality module: Knupp's shape metric per element type, on
// the element's nodes as 3D points in VTK order (z = 0 for a 2D mesh).
// `orientation` (+1/-1) multiplies every Jacobian determinant, so an element
// whose reference was mirrored scores as the unmirrored one.
// Formulas and their sources: docs/QUALITY.md.
#include <span>

#include "dgwarp/quality/corner_jacobian.hpp"

namespace dgwarp::quality_detail {

// Simplices (simplex_quality.cpp): one corner, signed by α.

/// Twice the signed area of triangle x[0..3) in the xy plane.
double triangle_alpha_2d(std::span<const Point3> x);
/// Knupp's triangle shape; `planar` (2D mesh): signed by orientation × α;
/// otherwise (a triangle in 3D space) α = |(x1-x0) × (x2-x0)|, unsigned.
double triangle_quality(std::span<const Point3> x, bool planar, int orientation);
/// Six times the signed volume of tetrahedron x[0..4).
double tetrahedron_alpha(std::span<const Point3> x);
/// Knupp's tetrahedron shape, signed by orientation × α.
double tetrahedron_quality(std::span<const Point3> x, int orientation);

// Corner-based elements (corner_quality.cpp).

/// Sum of the corner determinants of quadrilateral x[0..4) in the xy plane.
double quadrilateral_alpha_sum_2d(std::span<const Point3> x);
/// Knupp's quadrilateral shape. `planar` (2D mesh): corners signed by
/// orientation × α_k; otherwise (a quadrilateral in 3D space) α_k is measured
/// along the quadrilateral's mean normal and orientation is ignored.
double quadrilateral_quality(std::span<const Point3> x, bool planar, int orientation);

/// Sum of the corner determinants of a hexahedron (8 nodes), prism (6) or
/// pyramid (5: its 4 base corners and 4 apex sub-corners).
double hexahedron_alpha_sum(std::span<const Point3> x);
double prism_alpha_sum(std::span<const Point3> x);
double pyramid_alpha_sum(std::span<const Point3> x);

/// Knupp's hexahedron shape; the prism and pyramid extensions of docs/QUALITY.md.
double hexahedron_quality(std::span<const Point3> x, int orientation);
double prism_quality(std::span<const Point3> x, int orientation);
double pyramid_quality(std::span<const Point3> x, int orientation);

}  // namespace dgwarp::quality_detail
