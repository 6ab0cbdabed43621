#include "dgwarp/cases/store.hpp"

#include <gmsh.h>

#include <cmath>
#include <string>
#include <vector>

#include "dgwarp/cases/gmsh_session.hpp"
#include "dgwarp/core/error.hpp"

namespace dgwarp {

namespace {

constexpr double box_x = 3, box_y = 2, box_z = 2.5;
constexpr double plate_half_x = 1.0, plate_half_y = 0.6, plate_half_thickness = 0.025;

// 0: store, 1: plate, 2: far field, by the face's centre of mass.
int classify(int tag, double plate_z) {
    double x, y, z;
    gmsh::model::occ::getCenterOfMass(2, tag, x, y, z);
    if (std::abs(x) > box_x - 1e-6 || std::abs(y) > box_y - 1e-6 || std::abs(z) > box_z - 1e-6) return 2;
    return std::abs(z - plate_z) <= plate_half_thickness + 1e-6 && std::abs(x) <= plate_half_x + 1e-6 ? 1 : 0;
}

}  // namespace

Mesh make_store(const StoreOptions& o) {
    if (!(o.store_radius > 0 && o.store_length > 2 * o.store_radius && o.h_store > 0 && o.h_plate > 0 &&
          o.growth > 0 && o.h_max > 0) ||
        !(o.plate_z - plate_half_thickness > 3 * o.store_radius))
        throw MeshError("store: sizes must be positive, the store longer than wide and the plate above it");
    Mesh mesh;
    detail::with_gmsh("store", 1, [&] {
        namespace occ = gmsh::model::occ;
        gmsh::option::setNumber("Mesh.Algorithm", 6);     // Frontal-Delaunay surfaces
        gmsh::option::setNumber("Mesh.Algorithm3D", 1);  // Delaunay (deterministic on one thread)
        gmsh::option::setNumber("Mesh.Optimize", 1);
        gmsh::option::setNumber("Mesh.MeshSizeExtendFromBoundary", 0);
        gmsh::option::setNumber("Mesh.MeshSizeFromPoints", 0);
        gmsh::option::setNumber("Mesh.MeshSizeFromCurvature", 0);
        gmsh::model::add("store");

        const double half = o.store_length / 2 - o.store_radius;
        const int cylinder = occ::addCylinder(-half, 0, 0, 2 * half, 0, 0, o.store_radius);
        const int nose = occ::addSphere(half, 0, 0, o.store_radius);
        const int tail = occ::addSphere(-half, 0, 0, o.store_radius);
        gmsh::vectorpair store, bodies, domain;
        std::vector<gmsh::vectorpair> map;
        occ::fuse({{3, cylinder}}, {{3, nose}, {3, tail}}, store, map);
        const int plate = occ::addBox(-plate_half_x, -plate_half_y, o.plate_z - plate_half_thickness, 2 * plate_half_x,
                                      2 * plate_half_y, 2 * plate_half_thickness);
        bodies = store;
        bodies.push_back({3, plate});
        const int box = occ::addBox(-box_x, -box_y, -box_z, 2 * box_x, 2 * box_y, 2 * box_z);
        occ::cut({{3, box}}, bodies, domain, map);
        occ::synchronize();

        gmsh::vectorpair surfaces;
        gmsh::model::getEntities(surfaces, 2);
        std::vector<int> tags[3];
        for (const auto& s : surfaces) tags[classify(s.second, o.plate_z)].push_back(s.second);
        for (const auto& t : tags)
            if (t.empty()) throw MeshError("store: a marker has no surface (OCC gave an unexpected model)");

        auto distance_to = [](const std::vector<int>& faces) {
            const int f = gmsh::model::mesh::field::add("Distance");
            gmsh::model::mesh::field::setNumbers(f, "FacesList", std::vector<double>(faces.begin(), faces.end()));
            gmsh::model::mesh::field::setNumber(f, "NNodesByEdge", 100);
            return f;
        };
        const int from_store = distance_to(tags[0]), from_plate = distance_to(tags[1]);
        auto graded = [&](double h, int field) {
            return std::to_string(h) + " + " + std::to_string(o.growth) + " * F" + std::to_string(field);
        };
        const int size = gmsh::model::mesh::field::add("MathEval");
        gmsh::model::mesh::field::setString(size, "F",
                                            "Min(" + std::to_string(o.h_max) + ", Min(" + graded(o.h_store, from_store) +
                                                ", " + graded(o.h_plate, from_plate) + "))");
        gmsh::model::mesh::field::setAsBackgroundMesh(size);
        gmsh::model::mesh::generate(3);
        mesh = detail::mesh_from_gmsh(3, {{"store", tags[0]}, {"plate", tags[1]}, {"farfield", tags[2]}});
    });
    return mesh;
}

}  // namespace dgwarp
