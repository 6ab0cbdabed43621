#include "dgwarp/cases/naca0012.hpp"

#include <gmsh.h>

#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "dgwarp/cases/gmsh_session.hpp"
#include "dgwarp/core/error.hpp"

namespace dgwarp {

Mesh make_naca0012(const Naca0012Options& o) {
    if (o.points_per_side < 4 || !(o.farfield_radius > 1.5) || o.farfield_points < 8 || !(o.growth > 0) ||
        o.sliver_half_width < 0 || !(o.sliver_length > 0) || o.sliver_half_width >= o.sliver_length)
        throw MeshError("naca0012: options out of range (points_per_side >= 4, farfield_radius > 1.5, "
                        "farfield_points >= 8, growth > 0, 0 <= sliver_half_width < sliver_length)");
    Mesh mesh;
    detail::with_gmsh("naca0012", 1, [&] {
        namespace geo = gmsh::model::geo;
        gmsh::option::setNumber("Mesh.Algorithm", 6);  // Frontal-Delaunay
        gmsh::option::setNumber("Mesh.MeshSizeExtendFromBoundary", 0);
        gmsh::option::setNumber("Mesh.MeshSizeFromPoints", 0);
        gmsh::option::setNumber("Mesh.MeshSizeFromCurvature", 0);
        gmsh::model::add("naca0012");
        const int n = o.points_per_side;
        // Airfoil points counter-clockwise from the trailing edge: upper side
        // back to front, then lower side front to back.
        std::vector<int> pts;
        for (int i = 0; i < 2 * n; ++i) {
            const bool upper = i <= n;
            const int k = upper ? n - i : i - n;  // k = 0 at the trailing edge, n at the leading edge
            // Half cosine, half uniform spacing: clustered at the leading edge
            // without the tiny trailing-edge segments of pure cosine spacing.
            const double x = 0.5 * (1 + std::cos(std::numbers::pi * k / n)) / 2 + 0.5 * (1 - double(k) / n);
            const double y = naca0012_half_thickness(x) * (upper ? 1 : -1);
            pts.push_back(geo::addPoint(x, k == 0 || k == n ? 0.0 : y, 0));
        }
        std::vector<int> airfoil;
        for (int i = 0; i < 2 * n; ++i) airfoil.push_back(geo::addLine(pts[i], pts[(i + 1) % (2 * n)]));
        const double cx = 0.5, r = o.farfield_radius;
        const int centre = geo::addPoint(cx, 0, 0);
        std::vector<int> corner;
        for (int q = 0; q < 4; ++q)
            corner.push_back(geo::addPoint(cx + r * std::cos(q * std::numbers::pi / 2),
                                           r * std::sin(q * std::numbers::pi / 2), 0));
        std::vector<int> far;
        for (int q = 0; q < 4; ++q) far.push_back(geo::addCircleArc(corner[q], centre, corner[(q + 1) % 4]));
        const int outer = geo::addCurveLoop(far), inner = geo::addCurveLoop(airfoil);
        const int surface = geo::addPlaneSurface({outer, inner});
        std::vector<int> sliver;
        if (o.sliver_half_width > 0)
            for (double s : {1.0, -1.0}) sliver.push_back(geo::addPoint(1 + o.sliver_length, s * o.sliver_half_width, 0));
        geo::synchronize();
        for (int c : airfoil) gmsh::model::mesh::setTransfiniteCurve(c, 2);  // the airfoil nodes are exactly pts
        for (int c : far) gmsh::model::mesh::setTransfiniteCurve(c, o.farfield_points / 4 + 1);
        for (int p : sliver) gmsh::model::mesh::embed(0, {p}, 2, surface);

        // Size: the local airfoil spacing (distance field from the airfoil's
        // points), growing linearly with the distance from the airfoil.
        const int dist = gmsh::model::mesh::field::add("Distance");
        gmsh::model::mesh::field::setNumbers(dist, "EdgesList", std::vector<double>(airfoil.begin(), airfoil.end()));
        gmsh::model::mesh::field::setNumber(dist, "NNodesByEdge", 20);
        const double h_airfoil = 1.0 / n, h_far = 2 * std::numbers::pi * r / o.farfield_points;
        const int size = gmsh::model::mesh::field::add("MathEval");
        gmsh::model::mesh::field::setString(size, "F", "Min(" + std::to_string(h_far) + ", " +
                                                           std::to_string(h_airfoil) + " + " +
                                                           std::to_string(o.growth) + " * F" + std::to_string(dist) + ")");
        gmsh::model::mesh::field::setAsBackgroundMesh(size);
        gmsh::model::mesh::generate(2);
        mesh = detail::mesh_from_gmsh(2, {{"airfoil", airfoil}, {"farfield", far}});
    });
    return mesh;
}

}  // namespace dgwarp
