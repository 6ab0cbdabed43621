// The Gmsh module's table (cases/gmsh_cases_module.hpp): its one exported symbol.
#include "dgwarp/cases/gmsh_cases_module.hpp"

extern "C" __attribute__((visibility("default"))) const dgwarp::detail::GmshCases* dgwarp_gmsh_cases() {
    static const dgwarp::detail::GmshCases table{dgwarp::detail::gmsh_cases_version,
                                                 &dgwarp::make_naca0012,
                                                 &dgwarp::make_sphere_box,
                                                 &dgwarp::make_store,
                                                 &dgwarp::make_two_element,
                                                 &dgwarp::make_wing_body,
                                                 &dgwarp::make_random_scene_mesh};
    return &table;
}
