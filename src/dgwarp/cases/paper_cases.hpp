#pragma once
// The paper's test cases by name, with their motions as library data, so
// tools and benchmarks can run them without files:
//
//   Mesh mesh = make_case("naca0012");
//   for (const CaseMotion& m : case_motions("naca0012", mesh)) ... m.spec ...
//
// Cases (docs/RESULTS.md says how each differs from the paper's mesh):
//   rect-box         section 3.1, Tables 1-4   (make_rect_box)
//   naca0012         section 3.2, Tables 5-6   (make_naca0012)
//   twisted-bar      section 4,   Tables 7-8   (make_twisted_bar)
//   squeezed-sphere  section 5,   Tables 9-10  (make_sphere_box; sizes 0, 1, 2)
//   wing-body        section 6,   Figs. 23-24  (make_wing_body; size 0 coarse, size 1 the paper's)
// and ours (issue #12: a body moving next to a fixed one):
//   two-element      a main airfoil and a slotted flap (make_two_element)
//   store            a store below a fixed plate (make_store)
#include <string>
#include <string_view>
#include <vector>

#include "dgwarp/mesh/mesh.hpp"
#include "dgwarp/motion/motion_spec.hpp"

namespace dgwarp {

/// The case names, in the paper's order.
std::vector<std::string> case_names();

/// How many sizes a case has (1; 3 for squeezed-sphere, 2 for wing-body).
int case_size_count(std::string_view name);

/// The mesh of case `name` at size `size` (0 = smallest, < case_size_count).
/// Deterministic. Throws Error for an unknown name or size, MeshError when
/// Gmsh fails.
Mesh make_case(std::string_view name, int size = 0);

/// One of a case's motions: a short name ("rotate-45"), what it does, and the
/// motion spec (one frame; markers not named stay fixed).
struct CaseMotion {
    std::string name;
    std::string description;
    MotionSpec spec;
};

/// The paper's motions of case `name` for its mesh `mesh` (as make_case made
/// it; per-node motions read the marker nodes from it):
///   rect-box:        rotate-30, rotate-45, rotate-60, rotate-90 about the centre (0, 0); translate (2, 2)
///   naca0012:        translate (2, 2); rotate-45 (counter-clockwise) about the quarter chord (0.25, 0)
///   twisted-bar:     twist: the bar's node at (x, y) turns about (x, 0), its section's centre,
///                    by 45°·x / (L/2), L the bar's length (the ends turn ±45°), given as a
///                    displacement per node (a shape deformation, the paper's dx, dy); twist-rotate-45:
///                    the twist followed by a rigid 45° rotation about the bar's centre
///   squeezed-sphere: squeeze: the sphere's node (x, y, z) moves to (1.1x, 1.1y, 0.8z), an ellipsoid
///   wing-body:       fold-20: the outer wing (marker "wing") turns 20° about its hinge line
///                    (wing_body_hinge(), along +x), tip up; body, symmetry and far field fixed
///   two-element:     flap-10, flap-20, flap-30, flap-40: the flap turns trailing edge down
///                    about two_element_hinge(); main element and far field fixed
///   store:           drop-pitch-10, -20, -30: the store drops by its diameter and pitches nose
///                    down about its centre; plate and far field fixed
/// Throws Error for an unknown name, MeshError when the mesh lacks the case's markers.
std::vector<CaseMotion> case_motions(std::string_view name, const Mesh& mesh);

}  // namespace dgwarp
