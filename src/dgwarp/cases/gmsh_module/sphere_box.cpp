#include "dgwarp/cases/sphere_box.hpp"

#include <gmsh.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "dgwarp/cases/gmsh_session.hpp"
#include "dgwarp/core/error.hpp"

namespace dgwarp {

Mesh make_sphere_box(const SphereBoxOptions& c) {
    if (!(c.h_sphere > 0 && c.h_max > 0 && c.growth > 0 && c.h_box > 0) || c.threads < 1)
        throw MeshError("sphere-box: mesh sizes, growth and threads must be positive");
    Mesh mesh;
    detail::with_gmsh("sphere-box", c.threads, [&] {
        gmsh::option::setNumber("Mesh.Algorithm", 6);     // Frontal-Delaunay surfaces
        gmsh::option::setNumber("Mesh.Algorithm3D", 1);  // Delaunay: HXT gave a different mesh on each run
        gmsh::option::setNumber("Mesh.Optimize", 1);  // removes the slivers Delaunay leaves (the paper's min is 0.41-0.71)
        gmsh::option::setNumber("Mesh.MeshSizeExtendFromBoundary", 0);
        gmsh::option::setNumber("Mesh.MeshSizeFromPoints", 0);
        gmsh::option::setNumber("Mesh.MeshSizeFromCurvature", 0);
        gmsh::model::add("sphere_box");
        const int box = gmsh::model::occ::addBox(-5, -5, -5, 10, 10, 10);
        const int sphere = gmsh::model::occ::addSphere(0, 0, 0, 1);
        gmsh::vectorpair out;
        std::vector<gmsh::vectorpair> map;
        gmsh::model::occ::cut({{3, box}}, {{3, sphere}}, out, map);
        gmsh::model::occ::synchronize();

        // Which surfaces are the sphere (its bounding box is within radius 1.01).
        gmsh::vectorpair surfaces;
        gmsh::model::getEntities(surfaces, 2);
        std::vector<int> sphere_tags, box_tags;
        for (const auto& [dim, tag] : surfaces) {
            double x0, y0, z0, x1, y1, z1;
            gmsh::model::getBoundingBox(dim, tag, x0, y0, z0, x1, y1, z1);
            const bool on_sphere = std::max({std::abs(x0), std::abs(y0), std::abs(z0), x1, y1, z1}) < 1.01;
            (on_sphere ? sphere_tags : box_tags).push_back(tag);
        }
        // Size: h_sphere on the sphere, growing linearly with the distance from
        // it up to h_max; near the box faces (within 1) it blends up to h_box,
        // so the box's node count is set by h_box alone.
        auto distance_to = [](const std::vector<int>& faces) {
            const int f = gmsh::model::mesh::field::add("Distance");
            gmsh::model::mesh::field::setNumbers(f, "FacesList", std::vector<double>(faces.begin(), faces.end()));
            gmsh::model::mesh::field::setNumber(f, "NNodesByEdge", 200);
            return f;
        };
        const int from_sphere = distance_to(sphere_tags), from_box = distance_to(box_tags);
        const int graded = gmsh::model::mesh::field::add("MathEval");
        gmsh::model::mesh::field::setString(graded, "F",
                                            "Min(" + std::to_string(c.h_max) + ", " + std::to_string(c.h_sphere) +
                                                " + " + std::to_string(c.growth) + " * F" +
                                                std::to_string(from_sphere) + ")");
        const int near_box = gmsh::model::mesh::field::add("Threshold");
        gmsh::model::mesh::field::setNumber(near_box, "IField", from_box);
        gmsh::model::mesh::field::setNumber(near_box, "LcMin", c.h_box);
        gmsh::model::mesh::field::setNumber(near_box, "LcMax", 1e-3);
        gmsh::model::mesh::field::setNumber(near_box, "DistMin", 0);
        gmsh::model::mesh::field::setNumber(near_box, "DistMax", 1);
        const int size = gmsh::model::mesh::field::add("Max");
        gmsh::model::mesh::field::setNumbers(size, "FieldsList", {double(graded), double(near_box)});
        gmsh::model::mesh::field::setAsBackgroundMesh(size);
        gmsh::model::mesh::generate(3);
        mesh = detail::mesh_from_gmsh(3, {{"sphere", sphere_tags}, {"box", box_tags}});
    });
    return mesh;
}

}  // namespace dgwarp
