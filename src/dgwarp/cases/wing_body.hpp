#pragma once
// The paper's wing-body case (section 6, Figs. 23-24): a wing on a fuselage,
// the outer wing folded by 20°. The paper's mesh (257,909 nodes, 1,507,462
// tetrahedra) is not published; this is a simple configuration built from the
// text, generated with Gmsh's library (OCC kernel; Delaunay 3D, one thread:
// deterministic).
//
// Geometry (mesh units; the half model, y >= 0):
//   fuselage  a capsule along x: radius 0.6, length 10 (nose at x = -5)
//   wing      elliptic sections 12 % thick, chord 2.2 at the root (y = 0, inside the
//             fuselage) to 0.9 at the tip (y = 6), leading edge from x = -1.1 to
//             x = 0.4 (swept back), straight between the two (a ruled loft)
//   hinge     a gap 0.06 wide across the wing at y = 0.9 (0.3 outside the fuselage)
//             splits it into a stub, fused to the fuselage, and the outer panel,
//             which folds about the line along x through (y, z) = (0.9, top of the
//             section at y = 0.9); the gap keeps the panel clear of the stub, so no
//             node is on both a moving and a static marker
//   box       [-25, 30] × [0, 25] × [-25, 25]; y = 0 is the symmetry plane
#include "dgwarp/mesh/mesh.hpp"
#include "dgwarp/motion/node_motion.hpp"

namespace dgwarp {

/// Mesh sizes: h_wing on the outer panel, h_body on the fuselage and the stub,
/// each growing by `growth` per unit distance from its surface, capped at h_max
/// (also the size on the box).
struct WingBodyOptions {
    double h_wing = 0.044;
    double h_body = 0.068;
    double growth = 0.058;
    double h_max = 1.5;
    int threads = 1;  // Gmsh threads (1: deterministic)
};

/// The case's two sizes: 0, coarse (for tests and `dgwarp bench --quick`);
/// 1, the paper's (257,909 nodes, 1,507,462 tetrahedra; ours in
/// docs/RESULTS-DISCUSSION.md). Throws MeshError for another size.
WingBodyOptions wing_body_size(int size);

/// The hinge line of the fold: a point on it and its unit direction (+x).
struct WingHinge {
    Vec3 point;
    Vec3 axis;
};

/// The hinge of make_wing_body's outer wing (fixed by the geometry above).
WingHinge wing_body_hinge();

/// The wing-body mesh: tetrahedra (positive volume), markers (triangles)
/// "body" (fuselage and wing stub), "wing" (the outer panel, the part that
/// folds), "symmetry" (y = 0) and "farfield" (the other five box faces). Nodes
/// in Gmsh's order. Deterministic for fixed options. The default options give
/// the paper's size (see docs/RESULTS-DISCUSSION.md for the counts). Throws
/// MeshError when Gmsh fails or an option is not positive.
Mesh make_wing_body(const WingBodyOptions& options = {});

}  // namespace dgwarp
