#pragma once
// Internal to the wing-body case: its geometry (wing_body.hpp), shared by the
// mesher (wing_body.cpp, in the Gmsh module) and the hinge (case_shapes.cpp).
namespace dgwarp::wing_body_geometry {

constexpr double fuselage_length = 10, fuselage_radius = 0.6;
constexpr double root_chord = 2.2, tip_chord = 0.9, semi_span = 6, root_leading_edge = -1.1, sweep = 1.5;
constexpr double thickness = 0.12;  // thickness / chord of the elliptic sections
constexpr double hinge_y = 0.9, gap = 0.06;
constexpr double box_x0 = -25, box_x1 = 30, box_y1 = 25, box_z = 25;

constexpr double chord_at(double y) { return root_chord + (tip_chord - root_chord) * y / semi_span; }

}  // namespace dgwarp::wing_body_geometry
