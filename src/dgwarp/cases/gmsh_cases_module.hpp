#pragma once
// Internal to dgwarp_cases: the meshes made with Gmsh live in a module of
// their own, libdgwarp_gmsh_cases.so, loaded (dlopen) the first time a case
// is meshed. Gmsh and the OpenCASCADE libraries it loads took 0.2 s and 49 MB
// at every start of every program linking them (measured: an empty program
// linking libgmsh), most of dgwarp's start-up, for the few commands that mesh.
//
// The module exports one function, dgwarp_gmsh_cases(), returning this table;
// dgwarp_cases defines make_naca0012, make_sphere_box, ... as calls through it.
// The module is found, in order: at $DGWARP_GMSH_CASES; beside the program
// or shared library holding dgwarp_cases, or in ../lib/dgwarp from its folder
// (an installed PREFIX/bin/dgwarp); in the build tree; where it is installed.
#include "dgwarp/cases/naca0012.hpp"
#include "dgwarp/cases/random_scene.hpp"
#include "dgwarp/cases/sphere_box.hpp"
#include "dgwarp/cases/store.hpp"
#include "dgwarp/cases/two_element.hpp"
#include "dgwarp/cases/wing_body.hpp"

namespace dgwarp::detail {

constexpr int gmsh_cases_version = 1;

struct GmshCases {
    int version = gmsh_cases_version;  // a module of another build is refused
    Mesh (*naca0012)(const Naca0012Options&) = nullptr;
    Mesh (*sphere_box)(const SphereBoxOptions&) = nullptr;
    Mesh (*store)(const StoreOptions&) = nullptr;
    Mesh (*two_element)(const TwoElementOptions&) = nullptr;
    Mesh (*wing_body)(const WingBodyOptions&) = nullptr;
    Mesh (*random_scene_mesh)(const RandomScene&) = nullptr;
};

}  // namespace dgwarp::detail

/// The module's one exported function.
extern "C" const dgwarp::detail::GmshCases* dgwarp_gmsh_cases();
