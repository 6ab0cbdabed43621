#pragma once
// The paper's second test case (section 3.2, Figs. 12-13): a NACA0012 airfoil
// (chord 1, leading edge at the origin) in a circular far field, meshed with
// unstructured triangles by Gmsh, with one sliver cell just behind the
// trailing edge.
#include "dgwarp/mesh/mesh.hpp"

namespace dgwarp {

struct Naca0012Options {
    int points_per_side = 100;     // airfoil segments per side (half cosine, half uniform spacing): 2·n airfoil nodes
    double farfield_radius = 10;   // far-field circle centred at (0.5, 0)
    int farfield_points = 40;      // nodes on the far-field circle
    double growth = 0.285;         // interior cell size = airfoil size + growth · distance from the airfoil
    /// The sliver: two embedded nodes at (1 + a, ±b) behind the trailing edge
    /// (1, 0), so close together (b << a) that the triangles on their edge are
    /// slivers. The defaults give a worst cell of quality 0.172 at about
    /// x = 1.024 (the paper's original minimum is 0.177). b = 0: no sliver.
    double sliver_length = 0.02;        // a
    double sliver_half_width = 0.0006;  // b
};

/// The NACA0012 mesh: 2D triangles (counter-clockwise), markers "airfoil" and
/// "farfield". The defaults give 1,656 nodes and 3,070 cells (the
/// paper: 1,647 and 3,054). Deterministic (Gmsh Frontal-Delaunay, one thread). Throws MeshError
/// when Gmsh fails or the options are out of range.
Mesh make_naca0012(const Naca0012Options& options = {});

/// Half-thickness of the NACA0012 at chord position x in [0, 1] (closed
/// trailing edge, coefficient -0.1036).
double naca0012_half_thickness(double x);

}  // namespace dgwarp
