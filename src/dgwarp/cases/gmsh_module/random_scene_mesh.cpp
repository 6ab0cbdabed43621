// make_random_scene_mesh: a random scene meshed by Gmsh.
#include <gmsh.h>

#include <algorithm>
#include <cmath>
#include <array>
#include <map>
#include <numbers>
#include <sstream>
#include <string>
#include <vector>

#include "dgwarp/cases/gmsh_session.hpp"
#include "dgwarp/cases/random_scene.hpp"
#include "dgwarp/core/error.hpp"

namespace dgwarp {

namespace {

// The scene's cell size as a Gmsh MathEval formula of the distances to the
// bodies (field `bodies`) and to the box (field `box`): h_w + growth d_bodies,
// at most max_size, and at most a quarter of d_bodies + d_box (the width of
// the gap a point is in: four cells across a gap between a body and the box).
std::string size_formula(const RandomScene& s, int bodies, int box) {
    std::ostringstream f;
    f.precision(17);
    f << "Min(" << s.max_size << ", Min(" << s.wall_size << " + " << s.growth << " * F" << bodies << ", 0.25 * (F"
      << bodies << " + F" << box << ")))";
    return f.str();
}

// The distance field from entities of dimension `dim` (1: curves, 2: surfaces).
int distance_field(int dim, const std::vector<int>& entities, int samples) {
    namespace field = gmsh::model::mesh::field;
    const int f = field::add("Distance");
    field::setNumbers(f, dim == 1 ? "EdgesList" : "FacesList", std::vector<double>(entities.begin(), entities.end()));
    field::setNumber(f, "NNodesByEdge", samples);
    return f;
}

// Meshes the current model with the scene's size field (size_formula of the
// distances to the bodies' and the box's entities, of dimension scene.dim - 1,
// sampled `body_samples` / `box_samples` times per entity) and returns it with
// a marker per body (`body_entities`, in scene.bodies order) and "walls".
Mesh generate_sized(const RandomScene& scene, const std::vector<std::vector<int>>& body_entities,
                    const std::vector<int>& walls, int body_samples, int box_samples) {
    std::vector<int> all_bodies;
    for (const auto& e : body_entities) all_bodies.insert(all_bodies.end(), e.begin(), e.end());
    namespace field = gmsh::model::mesh::field;
    const int from_bodies = distance_field(scene.dim - 1, all_bodies, body_samples);
    const int from_box = distance_field(scene.dim - 1, walls, box_samples);
    const int size = field::add("MathEval");
    field::setString(size, "F", size_formula(scene, from_bodies, from_box));
    field::setAsBackgroundMesh(size);
    gmsh::model::mesh::generate(scene.dim);
    std::vector<std::pair<std::string, std::vector<int>>> markers;
    for (std::size_t i = 0; i < scene.bodies.size(); ++i) markers.push_back({scene.bodies[i].marker, body_entities[i]});
    markers.push_back({"walls", walls});
    return detail::mesh_from_gmsh(scene.dim, markers);
}

// The closed polygon resampled at n points evenly spaced along it, starting at its first point.
std::vector<double> resampled(const std::vector<double>& polygon, int n) {
    const std::size_t m = polygon.size() / 2;
    std::vector<double> along{0};
    for (std::size_t k = 0; k < m; ++k) {
        const std::size_t j = (k + 1) % m;
        along.push_back(along.back() + std::hypot(polygon[2 * j] - polygon[2 * k], polygon[2 * j + 1] - polygon[2 * k + 1]));
    }
    std::vector<double> out;
    std::size_t k = 0;
    for (int i = 0; i < n; ++i) {
        const double s = along.back() * i / n;
        while (along[k + 1] < s) ++k;
        const std::size_t j = (k + 1) % m;
        const double t = (s - along[k]) / std::max(along[k + 1] - along[k], 1e-300);
        out.push_back(polygon[2 * k] + t * (polygon[2 * j] - polygon[2 * k]));
        out.push_back(polygon[2 * k + 1] + t * (polygon[2 * j + 1] - polygon[2 * k + 1]));
    }
    return out;
}

double perimeter(const std::vector<double>& polygon) {
    double p = 0;
    const std::size_t n = polygon.size() / 2;
    for (std::size_t k = 0; k < n; ++k) {
        const std::size_t j = (k + 1) % n;
        p += std::hypot(polygon[2 * j] - polygon[2 * k], polygon[2 * j + 1] - polygon[2 * k + 1]);
    }
    return p;
}

// A body's boundary layers, made here (Gmsh 4.8's BoundaryLayer field
// crashes on some of these scenes): rings 0 (the outline, counter-clockwise)
// to `layers` offset along the vertex normals by first (ratio^j - 1) / (ratio - 1).
struct BodyLayers {
    int n = 0;                  // points per ring
    int layers = 0;
    std::vector<double> rings;  // (layers + 1) × n × 2
    const double* at(int ring, int k) const { return rings.data() + (static_cast<std::size_t>(ring) * n + k % n) * 2; }
};

BodyLayers body_layers(const std::vector<double>& outline, int layers, double first, double ratio) {
    BodyLayers l;
    l.n = static_cast<int>(outline.size() / 2);
    l.layers = layers;
    l.rings.resize(static_cast<std::size_t>(layers + 1) * l.n * 2);
    const int n = l.n;
    for (int k = 0; k < n; ++k) {
        const double* p = outline.data() + 2 * k;
        const double* prev = outline.data() + 2 * ((k + n - 1) % n);
        const double* next = outline.data() + 2 * ((k + 1) % n);
        // Outward normals of the two edges (the outline is counter-clockwise), and the mitre.
        double n1[2] = {p[1] - prev[1], prev[0] - p[0]}, n2[2] = {next[1] - p[1], p[0] - next[0]};
        const double l1 = std::hypot(n1[0], n1[1]), l2 = std::hypot(n2[0], n2[1]);
        double m[2] = {n1[0] / l1 + n2[0] / l2, n1[1] / l1 + n2[1] / l2};
        const double lm = std::hypot(m[0], m[1]);
        // The mitre 1 / cos(half the turn) up to 2; at a sharper corner (a
        // trailing edge) 1, so that the two sides' layers open a wedge there.
        const double scale = (lm / 2 < 0.5 ? 1.0 : 2.0 / lm) / lm;
        for (int j = 0; j <= layers; ++j) {
            const double d = first * (std::pow(ratio, j) - 1) / (ratio - 1);
            l.rings[(static_cast<std::size_t>(j) * n + k) * 2] = p[0] + d * m[0] * scale;
            l.rings[(static_cast<std::size_t>(j) * n + k) * 2 + 1] = p[1] + d * m[1] * scale;
        }
    }
    return l;
}

// 2D, the geo kernel: the box and each body a loop of four splines through
// its outline (the NACA's first point is its trailing edge: a corner there);
// with boundary layers, the outermost ring as a polyline of single-edge lines
// and the layers' quadrilaterals added after Gmsh's triangles.
Mesh mesh_2d(const RandomScene& scene) {
    namespace geo = gmsh::model::geo;
    gmsh::option::setNumber("Mesh.Algorithm", 6);  // Frontal-Delaunay
    gmsh::option::setNumber("Mesh.MeshSizeExtendFromBoundary", 0);
    gmsh::option::setNumber("Mesh.MeshSizeFromPoints", 0);
    gmsh::option::setNumber("Mesh.MeshSizeFromCurvature", 0);
    gmsh::model::add("random-scene");
    const double hx = scene.box_half[0], hy = scene.box_half[1];
    const int c[4] = {geo::addPoint(-hx, -hy, 0), geo::addPoint(hx, -hy, 0), geo::addPoint(hx, hy, 0),
                      geo::addPoint(-hx, hy, 0)};
    std::vector<int> walls;
    for (int k = 0; k < 4; ++k) walls.push_back(geo::addLine(c[k], c[(k + 1) % 4]));
    std::vector<int> loops{geo::addCurveLoop(walls)};
    std::vector<std::vector<int>> body_curves;  // the Gmsh curves of each body (its outer ring with layers)
    std::vector<int> single_edges;
    std::vector<BodyLayers> layers;
    // First layer 0.3 h_w, ratio 1.2: the layers end near the wall cell size.
    const double first = 0.3 * scene.wall_size, ratio = 1.2;
    for (const SceneBody& b : scene.bodies) {
        const double length = perimeter(body_outline(b, 2, 200));
        std::vector<int> curves;
        if (scene.boundary_layers > 0) {
            // One outline point per wall cell: the layers' quadrilaterals are that long.
            const int n = std::clamp(static_cast<int>(length / scene.wall_size), 48, 2400);
            layers.push_back(body_layers(resampled(body_outline(b, 2, 4000), n), scene.boundary_layers, first, ratio));
            const BodyLayers& l = layers.back();
            std::vector<int> points;
            for (int k = 0; k < l.n; ++k) points.push_back(geo::addPoint(l.at(l.layers, k)[0], l.at(l.layers, k)[1], 0));
            for (int k = 0; k < l.n; ++k) curves.push_back(geo::addLine(points[k], points[(k + 1) % l.n]));
            single_edges.insert(single_edges.end(), curves.begin(), curves.end());
        } else {
            // About 4 outline points per wall cell along the outline, for the splines' shape.
            const int n = std::clamp(static_cast<int>(4 * length / scene.wall_size) / 4 * 4, 64, 2400);
            const std::vector<double> outline = body_outline(b, 2, n);
            const int m = static_cast<int>(outline.size() / 2);
            std::vector<int> points;
            for (int k = 0; k < m; ++k) points.push_back(geo::addPoint(outline[2 * k], outline[2 * k + 1], 0));
            for (int q = 0; q < 4; ++q) {
                std::vector<int> through;
                for (int k = q * m / 4; k <= (q + 1) * m / 4; ++k) through.push_back(points[k % m]);
                curves.push_back(geo::addSpline(through));
            }
        }
        loops.push_back(geo::addCurveLoop(curves));
        body_curves.push_back(curves);
    }
    geo::addPlaneSurface(loops);
    geo::synchronize();
    for (int line : single_edges) gmsh::model::mesh::setTransfiniteCurve(line, 2);

    Mesh mesh = generate_sized(scene, body_curves, walls, scene.boundary_layers > 0 ? 4 : 400, 2000);
    if (layers.empty()) return mesh;

    // The layers: ring `layers` is Gmsh's (its nodes found by their coordinates,
    // which Gmsh copies from the points), rings 0 .. layers-1 new nodes.
    Mesh out = mesh;
    out.markers.clear();
    for (std::size_t i = 0; i < layers.size(); ++i) {
        const BodyLayers& l = layers[i];
        std::map<std::pair<double, double>, NodeId> outer;
        for (NodeId node : marker_nodes(mesh.markers[i]))
            outer[{mesh.points[2 * static_cast<std::size_t>(node)], mesh.points[2 * static_cast<std::size_t>(node) + 1]}] = node;
        std::vector<NodeId> ids(static_cast<std::size_t>(l.layers + 1) * l.n);
        for (int k = 0; k < l.n; ++k) {
            const auto found = outer.find({l.at(l.layers, k)[0], l.at(l.layers, k)[1]});
            if (found == outer.end() || outer.size() != static_cast<std::size_t>(l.n))
                throw MeshError("random scene: Gmsh moved the boundary layer's outer ring of " + scene.bodies[i].marker);
            ids[static_cast<std::size_t>(l.layers) * l.n + k] = found->second;
        }
        for (int j = 0; j < l.layers; ++j)
            for (int k = 0; k < l.n; ++k) {
                ids[static_cast<std::size_t>(j) * l.n + k] = static_cast<NodeId>(out.num_points());
                out.points.insert(out.points.end(), {l.at(j, k)[0], l.at(j, k)[1]});
            }
        const auto id = [&](int j, int k) { return ids[static_cast<std::size_t>(j) * l.n + k % l.n]; };
        for (int j = 0; j < l.layers; ++j)
            for (int k = 0; k < l.n; ++k) {
                // Counter-clockwise: out along k, along the outer ring, back in along k + 1.
                const std::array<NodeId, 4> q{id(j, k), id(j + 1, k), id(j + 1, k + 1), id(j, k + 1)};
                const double* p0 = l.at(j, k);
                const double* p1 = l.at(j + 1, k);
                const double* p3 = l.at(j, k + 1);
                const double* p2 = l.at(j + 1, k + 1);
                const double area = (p0[0] * p1[1] - p1[0] * p0[1]) + (p1[0] * p2[1] - p2[0] * p1[1]) +
                                    (p2[0] * p3[1] - p3[0] * p2[1]) + (p3[0] * p0[1] - p0[0] * p3[1]);
                if (!(area > 0))
                    throw MeshError("random scene: the boundary layer of " + scene.bodies[i].marker + " folds at layer " +
                                    std::to_string(j) + ", point " + std::to_string(k));
                out.cells.push_back(CellType::quadrilateral, q);
            }
        Marker body{scene.bodies[i].marker, {}};
        for (int k = 0; k < l.n; ++k) body.elements.push_back(CellType::line, std::array<NodeId, 2>{id(0, k), id(0, k + 1)});
        out.markers.push_back(std::move(body));
    }
    out.markers.push_back(mesh.markers.back());  // walls
    return out;
}

// 3D, the OCC kernel: each body a solid, cut from the box.
Mesh mesh_3d(const RandomScene& scene) {
    namespace occ = gmsh::model::occ;
    // Delaunay surfaces: with Frontal-Delaunay ones the volume mesher failed
    // on seed 3 ("No elements in volume").
    gmsh::option::setNumber("Mesh.Algorithm", 5);
    gmsh::option::setNumber("Mesh.Algorithm3D", 1);  // Delaunay (deterministic on one thread)
    gmsh::option::setNumber("Mesh.Optimize", 1);
    gmsh::option::setNumber("Mesh.MeshSizeExtendFromBoundary", 0);
    gmsh::option::setNumber("Mesh.MeshSizeFromPoints", 0);
    gmsh::option::setNumber("Mesh.MeshSizeFromCurvature", 0);
    gmsh::model::add("random-scene");
    gmsh::vectorpair tools;
    std::vector<gmsh::vectorpair> map;
    for (const SceneBody& b : scene.bodies) {
        const auto& q = b.parameters;
        gmsh::vectorpair solid;
        switch (b.shape) {
            case SceneShape::spheroid: {
                const int s = occ::addSphere(0, 0, 0, 0.5);
                solid = {{3, s}};
                occ::dilate(solid, 0, 0, 0, 1, q[0], q[0]);
                break;
            }
            case SceneShape::capsule: {
                const double r = q[0], half = 0.5 - r;
                const int cyl = occ::addCylinder(-half, 0, 0, 2 * half, 0, 0, r);
                const int a = occ::addSphere(-half, 0, 0, r), e = occ::addSphere(half, 0, 0, r);
                occ::fuse({{3, cyl}}, {{3, a}, {3, e}}, solid, map);
                break;
            }
            case SceneShape::rounded_box: {
                const double w = q[0], h = q[1];
                const int box = occ::addBox(-0.5, -w / 2, -h / 2, 1, w, h);
                occ::synchronize();
                gmsh::vectorpair faces, edges;  // the box's faces, then their curves (recursive would give points)
                gmsh::model::getBoundary({{3, box}}, faces, false, false, false);
                gmsh::model::getBoundary(faces, edges, false, false, false);
                std::vector<int> curves;
                for (const auto& e : edges)
                    if (e.first == 1) curves.push_back(std::abs(e.second));
                std::sort(curves.begin(), curves.end());
                curves.erase(std::unique(curves.begin(), curves.end()), curves.end());
                occ::fillet({box}, curves, {std::min(q[2], 0.45 * std::min(w, h))}, solid);
                break;
            }
            case SceneShape::wing: {
                const double t = q[0], span = q[1];
                std::vector<int> points;
                const int around = 80;
                // From the (sharp) trailing edge along the lower side to the
                // leading edge and back: two splines meeting at both edges. A
                // single spline closed on itself is periodic: it turns round
                // the trailing edge in a tiny loop, which Gmsh's surface
                // mesher refines for minutes (seeds 1, 4, 5, 13, ... timed out).
                for (int k = 0; k < around; ++k) {
                    const double s = 2.0 * k / around;
                    const double x = 0.5 * (1 + std::cos(std::numbers::pi * (s <= 1 ? s : 2 - s)));
                    const double th = 5 * t * (0.2969 * std::sqrt(x) - 0.1260 * x - 0.3516 * x * x +
                                               0.2843 * x * x * x - 0.1036 * x * x * x * x);
                    points.push_back(occ::addPoint(x - 0.5, s <= 1 ? -th : th, -span / 2));
                }
                points.push_back(points.front());
                const std::vector<int> lower(points.begin(), points.begin() + around / 2 + 1);
                const std::vector<int> upper(points.begin() + around / 2, points.end());
                const int wire = occ::addWire({occ::addSpline(lower), occ::addSpline(upper)});
                const int face = occ::addPlaneSurface({wire});
                gmsh::vectorpair out;
                occ::extrude({{2, face}}, 0, 0, span, out);
                for (const auto& e : out)
                    if (e.first == 3) solid.push_back(e);
                break;
            }
            default: throw MeshError("random scene: " + scene_shape_name(b.shape) + " is not a 3D shape");
        }
        occ::dilate(solid, 0, 0, 0, b.length, b.length, b.length);
        const double angle = std::sqrt(b.orientation[0] * b.orientation[0] + b.orientation[1] * b.orientation[1] +
                                       b.orientation[2] * b.orientation[2]);
        if (angle > 0)
            occ::rotate(solid, 0, 0, 0, b.orientation[0] / angle, b.orientation[1] / angle, b.orientation[2] / angle,
                        angle);
        occ::translate(solid, b.centre[0], b.centre[1], b.centre[2]);
        tools.insert(tools.end(), solid.begin(), solid.end());
    }
    const Vec3& h = scene.box_half;
    const int box = occ::addBox(-h[0], -h[1], -h[2], 2 * h[0], 2 * h[1], 2 * h[2]);
    gmsh::vectorpair domain;
    occ::cut({{3, box}}, tools, domain, map);
    occ::synchronize();

    // Surfaces: the box's (on its faces), else the body nearest a point of them.
    gmsh::vectorpair surfaces;
    gmsh::model::getEntities(surfaces, 2);
    std::vector<std::vector<int>> body_faces(scene.bodies.size());
    std::vector<int> walls;
    std::vector<std::vector<double>> outlines;  // per body, points on its surface: which body a surface is
    for (const SceneBody& b : scene.bodies) outlines.push_back(body_outline(b, 3, 2000));
    for (const auto& [dim, tag] : surfaces) {
        std::vector<double> lo, hi, xyz;
        gmsh::model::getParametrizationBounds(2, tag, lo, hi);
        gmsh::model::getValue(2, tag, {(lo[0] + hi[0]) / 2, (lo[1] + hi[1]) / 2}, xyz);
        bool on_box = false;
        double bx0, by0, bz0, bx1, by1, bz1;
        gmsh::model::getBoundingBox(2, tag, bx0, by0, bz0, bx1, by1, bz1);
        const double lo3[3] = {bx0, by0, bz0}, hi3[3] = {bx1, by1, bz1};
        for (int d = 0; d < 3; ++d)
            on_box |= (std::abs(lo3[d] + h[d]) < 1e-6 && std::abs(hi3[d] + h[d]) < 1e-6) ||
                      (std::abs(lo3[d] - h[d]) < 1e-6 && std::abs(hi3[d] - h[d]) < 1e-6);
        if (on_box) {
            walls.push_back(tag);
            continue;
        }
        std::size_t best = 0;
        double best_distance = 1e300;
        for (std::size_t i = 0; i < scene.bodies.size(); ++i) {
            const std::vector<double>& o = outlines[i];
            for (std::size_t k = 0; k < o.size(); k += 3) {
                const double d = std::hypot(o[k] - xyz[0], o[k + 1] - xyz[1], o[k + 2] - xyz[2]);
                if (d < best_distance) {
                    best_distance = d;
                    best = i;
                }
            }
        }
        body_faces[best].push_back(tag);
    }
    for (std::size_t i = 0; i < body_faces.size(); ++i)
        if (body_faces[i].empty())
            throw MeshError("random scene: " + scene.bodies[i].marker + " has no surface (OCC gave an unexpected model)");

    return generate_sized(scene, body_faces, walls, 100, 100);
}

}  // namespace

Mesh make_random_scene_mesh(const RandomScene& scene) {
    Mesh mesh;
    detail::with_gmsh("random scene " + std::to_string(scene.dim) + "D seed " + std::to_string(scene.seed), 1,
                      [&] { mesh = scene.dim == 2 ? mesh_2d(scene) : mesh_3d(scene); });
    return mesh;
}

}  // namespace dgwarp
