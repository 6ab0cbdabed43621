#include "dgwarp/cases/two_element.hpp"

#include <gmsh.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "dgwarp/cases/gmsh_session.hpp"
#include "dgwarp/cases/naca0012.hpp"
#include "dgwarp/core/error.hpp"

namespace dgwarp {

namespace {

// The points of a NACA0012 of chord `chord` with its leading edge at (x0, y0),
// counter-clockwise from the trailing edge (half cosine, half uniform spacing,
// as make_naca0012), added to the current Gmsh model; returns the closed
// polyline's line tags.
std::vector<int> add_airfoil(int n, double chord, double x0, double y0) {
    namespace geo = gmsh::model::geo;
    std::vector<int> pts;
    for (int i = 0; i < 2 * n; ++i) {
        const bool upper = i <= n;
        const int k = upper ? n - i : i - n;  // 0 at the trailing edge, n at the leading edge
        const double x = 0.5 * (1 + std::cos(std::numbers::pi * k / n)) / 2 + 0.5 * (1 - double(k) / n);
        const double y = k == 0 || k == n ? 0.0 : naca0012_half_thickness(x) * (upper ? 1 : -1);
        pts.push_back(geo::addPoint(x0 + chord * x, y0 + chord * y, 0));
    }
    std::vector<int> lines;
    for (int i = 0; i < 2 * n; ++i) lines.push_back(geo::addLine(pts[i], pts[(i + 1) % (2 * n)]));
    return lines;
}

}  // namespace

Mesh make_two_element(const TwoElementOptions& o) {
    if (o.main_points_per_side < 8 || o.flap_points_per_side < 8 || !(o.flap_chord > 0 && o.flap_chord < 1) ||
        !(o.farfield_radius > 2) || o.farfield_points < 8 || !(o.growth > 0))
        throw MeshError("two-element: options out of range (points per side >= 8, 0 < flap_chord < 1, "
                        "farfield_radius > 2, farfield_points >= 8, growth > 0)");
    Mesh mesh;
    detail::with_gmsh("two-element", 1, [&] {
        namespace geo = gmsh::model::geo;
        gmsh::option::setNumber("Mesh.Algorithm", 6);  // Frontal-Delaunay
        gmsh::option::setNumber("Mesh.MeshSizeExtendFromBoundary", 0);
        gmsh::option::setNumber("Mesh.MeshSizeFromPoints", 0);
        gmsh::option::setNumber("Mesh.MeshSizeFromCurvature", 0);
        gmsh::model::add("two-element");
        const std::vector<int> main = add_airfoil(o.main_points_per_side, 1.0, 0, 0);
        const std::vector<int> flap =
            add_airfoil(o.flap_points_per_side, o.flap_chord, o.flap_leading_edge[0], o.flap_leading_edge[1]);
        const double cx = 0.6, r = o.farfield_radius;
        const int centre = geo::addPoint(cx, 0, 0);
        std::vector<int> corner;
        for (int q = 0; q < 4; ++q)
            corner.push_back(geo::addPoint(cx + r * std::cos(q * std::numbers::pi / 2), r * std::sin(q * std::numbers::pi / 2), 0));
        std::vector<int> far;
        for (int q = 0; q < 4; ++q) far.push_back(geo::addCircleArc(corner[q], centre, corner[(q + 1) % 4]));
        geo::addPlaneSurface({geo::addCurveLoop(far), geo::addCurveLoop(main), geo::addCurveLoop(flap)});
        geo::synchronize();
        for (const auto* curves : {&main, &flap})
            for (int c : *curves) gmsh::model::mesh::setTransfiniteCurve(c, 2);  // the airfoil nodes are exactly the points
        for (int c : far) gmsh::model::mesh::setTransfiniteCurve(c, o.farfield_points / 4 + 1);

        // Size: the flap's wall spacing (the finer one) near both bodies,
        // growing linearly with the distance from them, at most the far field's.
        std::vector<double> walls(main.begin(), main.end());
        walls.insert(walls.end(), flap.begin(), flap.end());
        const int dist = gmsh::model::mesh::field::add("Distance");
        gmsh::model::mesh::field::setNumbers(dist, "EdgesList", walls);
        gmsh::model::mesh::field::setNumber(dist, "NNodesByEdge", 10);
        const double h_wall = o.flap_chord / o.flap_points_per_side;
        const double h_far = 2 * std::numbers::pi * r / o.farfield_points;
        const int size = gmsh::model::mesh::field::add("MathEval");
        gmsh::model::mesh::field::setString(size, "F", "Min(" + std::to_string(h_far) + ", " + std::to_string(h_wall) +
                                                           " + " + std::to_string(o.growth) + " * F" +
                                                           std::to_string(dist) + ")");
        gmsh::model::mesh::field::setAsBackgroundMesh(size);
        gmsh::model::mesh::generate(2);
        mesh = detail::mesh_from_gmsh(2, {{"main", main}, {"flap", flap}, {"farfield", far}});
    });
    return mesh;
}

}  // namespace dgwarp
