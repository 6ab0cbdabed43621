#pragma once
// A test case of ours, not the paper's (issue #12): a store (a body of
// revolution: a cylinder with hemispherical ends) released below a fixed flat
// plate of finite thickness, in a box; tetrahedra by Gmsh. The store drops by
// one diameter and pitches nose down: a body moving next to a fixed one in 3D.
//
// Geometry (length unit: the store's diameter 0.2): store axis along x through
// the origin, length store_length; plate 2 × 1.2 × 0.05 centred at
// (0, 0, plate_z); box [-3, 3] × [-2, 2] × [-2.5, 2.5].
#include <array>

#include "dgwarp/mesh/mesh.hpp"

namespace dgwarp {

struct StoreOptions {
    double store_radius = 0.1;
    double store_length = 1.2;   // tip to tip
    double plate_z = 0.4;        // the plate's mid-plane: its lower face is 0.25 above the store
    double h_store = 0.035;      // mesh size on the store
    double h_plate = 0.06;       // on the plate
    double growth = 0.25;        // size + growth · distance
    double h_max = 0.6;
};

/// The store's centre (its rotation centre in the motions): the origin.
std::array<double, 3> store_centre();

/// The mesh: 3D tetrahedra, markers "store", "plate" and "farfield".
/// Deterministic (Gmsh Delaunay, one thread). Throws MeshError when Gmsh fails
/// or the options are out of range.
Mesh make_store(const StoreOptions& options = {});

}  // namespace dgwarp
