#include "dgwarp/cases/paper_cases.hpp"

#include <cmath>
#include <numbers>

#include "dgwarp/cases/naca0012.hpp"
#include "dgwarp/cases/rect_box.hpp"
#include "dgwarp/cases/sphere_box.hpp"
#include "dgwarp/cases/store.hpp"
#include "dgwarp/cases/twisted_bar.hpp"
#include "dgwarp/cases/two_element.hpp"
#include "dgwarp/cases/wing_body.hpp"
#include "dgwarp/core/error.hpp"

namespace dgwarp {

namespace {

constexpr double degree = std::numbers::pi / 180;

std::string known_cases() {
    std::string s;
    for (const auto& n : case_names()) s += (s.empty() ? "" : ", ") + n;
    return s;
}

/// One frame in which marker `marker` moves by `motion`.
MotionSpec one_marker(const std::string& marker, MarkerMotion motion) {
    MotionSpec spec;
    spec.frames.push_back(MotionFrame{{{marker, std::move(motion)}}});
    return spec;
}

CaseMotion rigid(const std::string& marker, std::string name, std::string description, double angle_degrees,
                 const Vec3& center, const Vec3& translation) {
    NodeMotion m;
    m.rotation = {0, 0, angle_degrees * degree};
    m.center = center;
    m.translation = translation;
    return {std::move(name), std::move(description), one_marker(marker, RigidMotion{m})};
}

/// The twisted bar's motion, optionally followed by a rotation by
/// `then_degrees` about the origin. The twist is a shape deformation, so it
/// enters as a displacement d per node, as the paper's dx, dy "due to
/// translation and shape deformation" (its Euler angles are the rigid
/// rotation's): node x of the section at abscissa x turns by θ(x) about (x, 0),
/// d = R(θ)(x - c) + c - x. The rotation that follows is rigid: rotation
/// vector φ about the origin and translation R(φ)d, so the node lands at
/// R(φ)(x + d).
CaseMotion twist(const Mesh& mesh, double then_degrees) {
    const std::vector<NodeId> nodes = marker_nodes(find_marker(mesh, "bar"));
    double x_max = 0;
    for (NodeId n : nodes) x_max = std::max(x_max, std::abs(mesh.points[2 * static_cast<std::size_t>(n)]));
    const double phi = then_degrees * degree;
    const double cos_phi = std::cos(phi), sin_phi = std::sin(phi);
    NodeTable<NodeMotion> table;
    table.components = 2;
    for (NodeId n : nodes) {
        const double x = mesh.points[2 * static_cast<std::size_t>(n)];
        const double y = mesh.points[2 * static_cast<std::size_t>(n) + 1];
        const double theta = 45 * degree * x / x_max;
        const double dx = -std::sin(theta) * y, dy = std::cos(theta) * y - y;  // R(θ)(0, y) - (0, y)
        NodeMotion m;
        m.center = {0, 0, 0};
        m.rotation = {0, 0, phi};
        m.translation = {cos_phi * dx - sin_phi * dy, sin_phi * dx + cos_phi * dy, 0};
        table.nodes.push_back(n);
        table.values.push_back(m);
    }
    if (then_degrees == 0)
        return {"twist", "sections turn about their centres by up to ±45° at the ends (a displacement per node)",
                one_marker("bar", PrescribedNodeMotions{std::move(table)})};
    return {"twist-rotate-45", "the twist, then a 45° rotation about the bar's centre",
            one_marker("bar", PrescribedNodeMotions{std::move(table)})};
}

CaseMotion squeeze(const Mesh& mesh) {
    const std::vector<NodeId> nodes = marker_nodes(find_marker(mesh, "sphere"));
    NodeTable<Vec3> table;
    table.components = 3;
    const Vec3 scale{1.1, 1.1, 0.8};
    for (NodeId n : nodes) {
        Vec3 d;
        for (int k = 0; k < 3; ++k) d[k] = (scale[k] - 1) * mesh.points[3 * static_cast<std::size_t>(n) + k];
        table.nodes.push_back(n);
        table.values.push_back(d);
    }
    return {"squeeze", "the unit sphere becomes the ellipsoid with semi-axes 1.1, 1.1, 0.8",
            one_marker("sphere", PrescribedDisplacements{std::move(table)})};
}

/// The outer wing folded up by 20° about its hinge line (wing-body.hpp).
CaseMotion fold(const Mesh& mesh) {
    (void)find_marker(mesh, "wing");  // throws MeshError when the mesh has no wing
    const WingHinge hinge = wing_body_hinge();
    NodeMotion m;
    for (int k = 0; k < 3; ++k) m.rotation[k] = 20 * degree * hinge.axis[k];
    m.center = hinge.point;
    return {"fold-20", "the outer wing folds up by 20° about its hinge line at the root",
            one_marker("wing", RigidMotion{m})};
}

}  // namespace

std::vector<std::string> case_names() {
    return {"rect-box", "naca0012", "twisted-bar", "squeezed-sphere", "wing-body", "two-element", "store"};
}

int case_size_count(std::string_view name) {
    if (name == "squeezed-sphere") return 3;
    if (name == "wing-body") return 2;
    for (const auto& n : case_names())
        if (n == name) return 1;
    throw Error("unknown case '" + std::string(name) + "'; the cases are " + known_cases());
}

Mesh make_case(std::string_view name, int size) {
    if (size < 0 || size >= case_size_count(name))
        throw Error("case '" + std::string(name) + "' has sizes 0 to " + std::to_string(case_size_count(name) - 1) +
                    ", not " + std::to_string(size));
    if (name == "rect-box") return make_rect_box();
    if (name == "naca0012") return make_naca0012();
    if (name == "twisted-bar") return make_twisted_bar();
    if (name == "wing-body") return make_wing_body(wing_body_size(size));
    if (name == "two-element") return make_two_element();
    if (name == "store") return make_store();
    return make_sphere_box(sphere_box_paper_size(size));
}

std::vector<CaseMotion> case_motions(std::string_view name, const Mesh& mesh) {
    case_size_count(name);  // throws for an unknown name
    if (name == "rect-box") {
        std::vector<CaseMotion> m;
        for (int a : {30, 45, 60, 90})
            m.push_back(rigid("rectangle", "rotate-" + std::to_string(a),
                              "the rectangle turns " + std::to_string(a) + "° about its centre", a, {0, 0, 0}, {0, 0, 0}));
        m.push_back(rigid("rectangle", "translate", "the rectangle moves by (2, 2)", 0, {0, 0, 0}, {2, 2, 0}));
        return m;
    }
    if (name == "naca0012")
        return {rigid("airfoil", "translate", "the airfoil moves by (2, 2)", 0, {0, 0, 0}, {2, 2, 0}),
                rigid("airfoil", "rotate-45", "the airfoil turns 45° counter-clockwise about (0.25, 0)", 45,
                      {0.25, 0, 0}, {0, 0, 0})};
    if (name == "twisted-bar") return {twist(mesh, 0), twist(mesh, 45)};
    if (name == "wing-body") return {fold(mesh)};
    if (name == "two-element") {
        const auto h = two_element_hinge();
        std::vector<CaseMotion> m;
        for (int a : {10, 20, 30, 40})
            m.push_back(rigid("flap", "flap-" + std::to_string(a),
                              "the flap deflects " + std::to_string(a) + "° trailing edge down about its hinge (" +
                                  std::to_string(h[0]).substr(0, 4) + ", " + std::to_string(h[1]).substr(0, 5) + ")",
                              -a, {h[0], h[1], 0}, {0, 0, 0}));
        return m;
    }
    if (name == "store") {
        // Nose (+x) down: a positive turn about +y; about the store's centre,
        // then a drop of one diameter.
        const StoreOptions o;
        std::vector<CaseMotion> m;
        for (int a : {10, 20, 30}) {
            NodeMotion motion;
            motion.rotation = {0, a * degree, 0};
            motion.center = {store_centre()[0], store_centre()[1], store_centre()[2]};
            motion.translation = {0, 0, -2 * o.store_radius};
            m.push_back({"drop-pitch-" + std::to_string(a),
                         "the store drops by its diameter and pitches " + std::to_string(a) + "° nose down",
                         one_marker("store", RigidMotion{motion})});
        }
        return m;
    }
    return {squeeze(mesh)};
}

}  // namespace dgwarp
