#pragma once
// A test case of ours, not the paper's (issue #12): a main airfoil and a
// slotted flap below its trailing edge, a gap of about 2% chord between them,
// in a circular far field; triangles by Gmsh. The flap deflects trailing edge
// down about a hinge just below its leading edge (so it turns away from the
// main element and the slot opens), the main element stays: the motion next
// to a fixed wall that folds the one-pass methods' cells.
#include <array>

#include "dgwarp/mesh/mesh.hpp"

namespace dgwarp {

struct TwoElementOptions {
    int main_points_per_side = 100;  // main element (NACA0012, chord 1, leading edge at the origin): 2·n nodes
    int flap_points_per_side = 50;   // flap (NACA0012 shape, chord flap_chord): 2·n nodes
    double flap_chord = 0.3;
    std::array<double, 2> flap_leading_edge{0.95, -0.04};  // under the main element's trailing edge (1, 0)
    double farfield_radius = 10;     // circle centred at (0.6, 0)
    int farfield_points = 48;
    double growth = 0.2;             // cell size = wall size + growth · distance from the airfoils
};

/// The hinge the flap turns about: 3% of the flap chord below its leading edge.
std::array<double, 2> two_element_hinge(const TwoElementOptions& options = {});

/// The mesh: 2D triangles, markers "main", "flap" and "farfield".
/// Deterministic (Gmsh Frontal-Delaunay, one thread). Throws MeshError when
/// Gmsh fails or the options are out of range.
Mesh make_two_element(const TwoElementOptions& options = {});

}  // namespace dgwarp
