// What the cases' headers declare besides their meshes: sizes, hinges,
// profiles. No Gmsh here: the meshes come from the Gmsh module
// (gmsh_cases_module.hpp), these are in dgwarp_cases itself.
#include <cmath>
#include <string>

#include "dgwarp/cases/naca0012.hpp"
#include "dgwarp/cases/sphere_box.hpp"
#include "dgwarp/cases/store.hpp"
#include "dgwarp/cases/two_element.hpp"
#include "dgwarp/cases/wing_body.hpp"
#include "dgwarp/cases/wing_body_geometry.hpp"
#include "dgwarp/core/error.hpp"

namespace dgwarp {

double naca0012_half_thickness(double x) {
    return 5 * 0.12 * (0.2969 * std::sqrt(x) - 0.1260 * x - 0.3516 * x * x + 0.2843 * x * x * x - 0.1036 * x * x * x * x);
}

WingBodyOptions wing_body_size(int size) {
    switch (size) {
        case 0: return {0.15, 0.2, 0.2, 3, 1};
        case 1: return {};
        default: throw MeshError("wing-body: size must be 0 or 1, not " + std::to_string(size));
    }
}

WingHinge wing_body_hinge() {
    using namespace wing_body_geometry;
    return {{0, hinge_y, thickness * chord_at(hinge_y) / 2}, {1, 0, 0}};
}

std::array<double, 2> two_element_hinge(const TwoElementOptions& o) {
    // Just below the leading edge: every point of the flap above the hinge
    // moves aft as the trailing edge goes down, so the flap turns away from
    // the main element and the slot opens.
    return {o.flap_leading_edge[0], o.flap_leading_edge[1] - 0.03 * o.flap_chord};
}

SphereBoxOptions sphere_box_paper_size(int size) {
    switch (size) {
        case 0: return {0.0444, 0.55, 0.0413, 0.55, 1};
        case 1: return {0.0444, 0.55, 0.025, 0.55, 1};
        case 2: return {0.025, 0.3, 0.028, 0.204, 1};
        default: throw MeshError("squeezed-sphere: size must be 0, 1 or 2, not " + std::to_string(size));
    }
}

std::array<double, 3> store_centre() { return {0, 0, 0}; }

}  // namespace dgwarp
