#include "dgwarp/cases/wing_body.hpp"

#include <gmsh.h>

#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "dgwarp/cases/gmsh_session.hpp"
#include "dgwarp/cases/wing_body_geometry.hpp"
#include "dgwarp/core/error.hpp"

namespace dgwarp {

namespace {

using namespace wing_body_geometry;

/// The wing's section at span station y: an ellipse in the plane y, chord along
/// x, thickness along z, as an OCC wire.
int section_wire(double y) {
    const double c = chord_at(y), x_center = root_leading_edge + sweep * y / semi_span + c / 2;
    const int e = gmsh::model::occ::addEllipse(x_center, y, 0, c / 2, thickness * c / 2);
    gmsh::model::occ::rotate({{1, e}}, x_center, y, 0, 1, 0, 0, std::numbers::pi / 2);  // xy plane -> xz plane
    return gmsh::model::occ::addWire({e});
}

/// Which marker surface `tag` belongs to: 0 body, 1 wing, 2 symmetry, 3 farfield.
int classify(int tag) {
    double x0, y0, z0, x1, y1, z1;
    gmsh::model::getBoundingBox(2, tag, x0, y0, z0, x1, y1, z1);
    constexpr double eps = 1e-4;
    auto flat_at = [&](double lo, double hi, double at) { return hi - lo < eps && std::abs(lo - at) < eps; };
    if (flat_at(y0, y1, 0)) return 2;
    if (flat_at(x0, x1, box_x0) || flat_at(x0, x1, box_x1) || flat_at(y0, y1, box_y1) || flat_at(z0, z1, -box_z) ||
        flat_at(z0, z1, box_z))
        return 3;
    double cx, cy, cz;  // OCC bounding boxes of curved faces are loose: the centre of mass is not
    gmsh::model::occ::getCenterOfMass(2, tag, cx, cy, cz);
    return cy > hinge_y ? 1 : 0;
}

}  // namespace

Mesh make_wing_body(const WingBodyOptions& c) {
    if (!(c.h_wing > 0 && c.h_body > 0 && c.growth > 0 && c.h_max > 0) || c.threads < 1)
        throw MeshError("wing-body: mesh sizes, growth and threads must be positive");
    Mesh mesh;
    detail::with_gmsh("wing-body", c.threads, [&] {
        namespace occ = gmsh::model::occ;
        gmsh::option::setNumber("Mesh.Algorithm", 6);     // Frontal-Delaunay surfaces
        gmsh::option::setNumber("Mesh.Algorithm3D", 1);  // Delaunay (HXT is not deterministic on threads)
        gmsh::option::setNumber("Mesh.Optimize", 1);     // removes Delaunay's slivers
        gmsh::option::setNumber("Mesh.MeshSizeExtendFromBoundary", 0);
        gmsh::option::setNumber("Mesh.MeshSizeFromPoints", 0);
        gmsh::option::setNumber("Mesh.MeshSizeFromCurvature", 0);
        gmsh::model::add("wing_body");

        // Fuselage: a cylinder with hemispherical ends (analytic surfaces; an
        // ellipsoid made by dilating a sphere becomes a B-spline, slow to mesh).
        const double half = fuselage_length / 2 - fuselage_radius;
        const int cylinder = occ::addCylinder(-half, 0, 0, 2 * half, 0, 0, fuselage_radius);
        const int nose = occ::addSphere(-half, 0, 0, fuselage_radius);
        const int tail = occ::addSphere(half, 0, 0, fuselage_radius);
        gmsh::vectorpair fuselage, pieces, body, domain;
        std::vector<gmsh::vectorpair> map;
        occ::fuse({{3, cylinder}}, {{3, nose}, {3, tail}}, fuselage, map);

        // Wing, cut by the hinge gap into the stub (fused to the fuselage) and the panel.
        gmsh::vectorpair wing;
        occ::addThruSections({section_wire(0), section_wire(semi_span)}, wing, -1, true, true);
        const int slab = occ::addBox(-2 * box_z, hinge_y - gap / 2, -box_z, 4 * box_z, gap, 2 * box_z);
        occ::cut(wing, {{3, slab}}, pieces, map);
        occ::synchronize();
        gmsh::vectorpair stub, panel;
        for (const auto& p : pieces) {
            double x, y, z;
            occ::getCenterOfMass(p.first, p.second, x, y, z);
            (y > hinge_y ? panel : stub).push_back(p);
        }
        if (stub.size() != 1 || panel.size() != 1)
            throw MeshError("wing-body: the hinge gap did not cut the wing into a stub and a panel");
        occ::fuse(fuselage, stub, body, map);
        body.insert(body.end(), panel.begin(), panel.end());
        const int box = occ::addBox(box_x0, 0, -box_z, box_x1 - box_x0, box_y1, 2 * box_z);
        occ::cut({{3, box}}, body, domain, map);
        occ::synchronize();

        gmsh::vectorpair surfaces;
        gmsh::model::getEntities(surfaces, 2);
        std::vector<int> tags[4];
        for (const auto& s : surfaces) tags[classify(s.second)].push_back(s.second);
        for (const auto& t : tags)
            if (t.empty()) throw MeshError("wing-body: a marker has no surface (OCC gave an unexpected model)");

        // Size: h_wing on the panel, h_body on the fuselage and stub, each
        // growing linearly with the distance from its surfaces, capped at h_max.
        auto distance_to = [](const std::vector<int>& faces) {
            const int f = gmsh::model::mesh::field::add("Distance");
            gmsh::model::mesh::field::setNumbers(f, "FacesList", std::vector<double>(faces.begin(), faces.end()));
            gmsh::model::mesh::field::setNumber(f, "NNodesByEdge", 200);
            return f;
        };
        const int from_body = distance_to(tags[0]), from_wing = distance_to(tags[1]);
        auto graded = [&](double h, int field) {
            return std::to_string(h) + " + " + std::to_string(c.growth) + " * F" + std::to_string(field);
        };
        const int size = gmsh::model::mesh::field::add("MathEval");
        gmsh::model::mesh::field::setString(size, "F",
                                            "Min(" + std::to_string(c.h_max) + ", Min(" + graded(c.h_wing, from_wing) +
                                                ", " + graded(c.h_body, from_body) + "))");
        gmsh::model::mesh::field::setAsBackgroundMesh(size);
        gmsh::model::mesh::generate(3);
        mesh = detail::mesh_from_gmsh(
            3, {{"body", tags[0]}, {"wing", tags[1]}, {"symmetry", tags[2]}, {"farfield", tags[3]}});
    });
    return mesh;
}

}  // namespace dgwarp
