// A program using only the deformation core and the mesh and motion files, as
// a flow solver coupling dgwarp does: read a mesh and a motion file, prepare
// DG-IDW once, deform frame 0, write the mesh. It links dgwarp_io and
// dgwarp_methods only (tests/CMakeLists.txt); tests/link/solver_link_test.cpp
// checks that this pulls in neither Cairo nor Gmsh, and that it deforms as the
// library does.
//
// Usage: solver_program MESH MOTION.json OUT
#include <iostream>

#include "dgwarp/core/error.hpp"
#include "dgwarp/io/mesh_io.hpp"
#include "dgwarp/io/motion_file.hpp"
#include "dgwarp/methods/method.hpp"
#include "dgwarp/motion/resolve_motion.hpp"

using namespace dgwarp;

int main(int argc, char** argv) {
    if (argc != 4) {
        std::cerr << "usage: " << argv[0] << " MESH MOTION.json OUT\n";
        return 1;
    }
    try {
        const Mesh mesh = read_mesh(argv[1]);
        const MotionSpec spec = read_motion_file(argv[2]);
        const ResolvedBoundary rb = resolve_boundary(mesh, spec);
        const Plan plan = prepare(Method::dg_idw, mesh.dim, mesh.points, rb.boundary);
        Mesh deformed = mesh;
        deform(plan, mesh.points, resolve_frame(mesh, spec, rb, 0).motion, deformed.points);
        write_mesh(argv[3], deformed);
        return 0;
    } catch (const Error& e) {
        std::cerr << "error: " << e.what() << "\n";
        return 2;
    }
}
