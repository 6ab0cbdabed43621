#include "dgwarp/motion/slide_planes.hpp"

#include <algorithm>
#include <array>
#include <cassert>
#include <cmath>
#include <numbers>
#include <string>

#include "dgwarp/core/error.hpp"

namespace dgwarp {

namespace {

using V3 = std::array<double, 3>;

V3 cross(const V3& a, const V3& b) {
    return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
double dot(const V3& a, const V3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
double norm(const V3& a) { return std::sqrt(dot(a, a)); }

/// Same plane below this angle between normals (radians), another plane above
/// crease_angle; in between, a curved marker.
constexpr double same_plane_angle = 1e-6;
constexpr double crease_angle = 0.5 * std::numbers::pi / 180;

V3 point_of(const Mesh& mesh, NodeId node) {
    const auto dim = static_cast<std::size_t>(mesh.dim);
    const double* x = mesh.points.data() + static_cast<std::size_t>(node) * dim;
    return {x[0], x[1], dim == 3 ? x[2] : 0.0};
}

/// The unit normal of a face (3D: Newell's normal of its polygon; 2D: of the
/// edge from its first to its last node), or zeros for a degenerate face.
V3 face_normal(const Mesh& mesh, std::span<const NodeId> nodes) {
    V3 n{0, 0, 0};
    if (mesh.dim == 2) {
        const V3 a = point_of(mesh, nodes.front()), b = point_of(mesh, nodes.back());
        n = {-(b[1] - a[1]), b[0] - a[0], 0};
    } else {
        for (std::size_t i = 0; i < nodes.size(); ++i) {
            const V3 a = point_of(mesh, nodes[i]), b = point_of(mesh, nodes[(i + 1) % nodes.size()]);
            n[0] += (a[1] - b[1]) * (a[2] + b[2]);
            n[1] += (a[2] - b[2]) * (a[0] + b[0]);
            n[2] += (a[0] - b[0]) * (a[1] + b[1]);
        }
    }
    const double l = norm(n);
    if (!(l > 0) || !std::isfinite(l)) return {0, 0, 0};
    return {n[0] / l, n[1] / l, n[2] / l};
}

struct NodeFace {
    NodeId node;
    V3 normal;
    std::size_t marker;
};

}  // namespace

SlidePlanes slide_planes(const Mesh& mesh, std::span<const std::size_t> markers, std::span<const NodeId> pinned) {
    assert(std::is_sorted(pinned.begin(), pinned.end()));
    // Every (node, face normal) of the sliding faces, for the nodes that slide.
    std::vector<NodeFace> faces;
    for (const std::size_t m : markers) {
        const ElementList& e = mesh.markers[m].elements;
        for (std::size_t f = 0; f < e.size(); ++f) {
            const auto nodes = e.nodes_of(f);
            const V3 n = face_normal(mesh, nodes);
            if (n == V3{0, 0, 0}) continue;
            for (const NodeId node : nodes)
                if (!std::binary_search(pinned.begin(), pinned.end(), node)) faces.push_back({node, n, m});
        }
    }
    std::sort(faces.begin(), faces.end(), [](const NodeFace& a, const NodeFace& b) { return a.node < b.node; });

    SlidePlanes out;
    SlideSet& s = out.slides;
    const auto dim = static_cast<std::size_t>(mesh.dim);
    const std::size_t max_planes = mesh.dim == 3 ? 2 : 1;
    const double sin_same = std::sin(same_plane_angle), sin_crease = std::sin(crease_angle);
    for (std::size_t i = 0; i < faces.size();) {
        const NodeId node = faces[i].node;
        std::size_t end = i;
        while (end < faces.size() && faces[end].node == node) ++end;
        // The node's planes: sums of the normals of each plane's faces (signs aligned).
        std::vector<V3> planes;
        for (std::size_t f = i; f < end; ++f) {
            const V3& n = faces[f].normal;
            bool placed = false;
            for (V3& p : planes) {
                const V3 u{p[0] / norm(p), p[1] / norm(p), p[2] / norm(p)};
                const double sine = norm(cross(u, n));
                if (sine < sin_same) {
                    const double sign = dot(u, n) < 0 ? -1.0 : 1.0;
                    for (int k = 0; k < 3; ++k) p[k] += sign * n[k];
                    placed = true;
                    break;
                }
                if (sine <= sin_crease) {
                    const double degrees = std::asin(std::min(1.0, sine)) * 180 / std::numbers::pi;
                    const std::string& marker = mesh.markers[faces[f].marker].name;
                    throw MeshError("marker '" + marker + "' slides but is not planar at node " + std::to_string(node) +
                                        ": faces there meet at " + std::to_string(degrees) +
                                        " degrees. A sliding node stays in the planes of its faces, so a sliding "
                                        "marker must be made of planes (meeting at more than 0.5 degrees where "
                                        "they meet); give a curved marker a motion, or \"fixed\"",
                                    marker, node);
                }
            }
            if (!placed) planes.push_back(n);
        }
        i = end;
        if (planes.size() > max_planes) {
            out.corners.push_back(node);
            continue;
        }
        V3 d = planes[0];
        if (planes.size() == 2) d = cross(planes[0], planes[1]);
        const double l = norm(d);
        s.nodes.push_back(node);
        s.planes.push_back(static_cast<std::uint8_t>(planes.size()));
        s.directions.insert(s.directions.end(), {d[0] / l, d[1] / l, d[2] / l});
        const double* x = mesh.points.data() + static_cast<std::size_t>(node) * dim;
        s.origins.insert(s.origins.end(), x, x + dim);
    }
    return out;
}

namespace {

/// Keeps only the part of `v` (dim values) in the node's plane or along its line.
void project_one(const SlideSet& slides, std::size_t i, std::size_t dim, double* v) {
    if (slides.planes[i] == 0) return;  // free
    const double* u = slides.directions.data() + i * 3;
    double along = 0;
    for (std::size_t k = 0; k < dim; ++k) along += v[k] * u[k];
    for (std::size_t k = 0; k < dim; ++k) v[k] = slides.planes[i] == 1 ? v[k] - along * u[k] : along * u[k];
}

}  // namespace

void apply_slides(const SlideSet& slides, int dim, std::span<double> points) {
    const auto d = static_cast<std::size_t>(dim);
    for (std::size_t i = 0; i < slides.size(); ++i) {
        double* x = points.data() + static_cast<std::size_t>(slides.nodes[i]) * d;
        const double* x0 = slides.origins.data() + i * d;
        double disp[3] = {0, 0, 0};
        for (std::size_t k = 0; k < d; ++k) disp[k] = x[k] - x0[k];
        project_one(slides, i, d, disp);
        for (std::size_t k = 0; k < d; ++k) x[k] = x0[k] + disp[k];
    }
}

void project_slide_vectors(const SlideSet& slides, int dim, std::span<double> vectors) {
    const auto d = static_cast<std::size_t>(dim);
    assert(vectors.size() == slides.size() * d);
    for (std::size_t i = 0; i < slides.size(); ++i) project_one(slides, i, d, vectors.data() + i * d);
}

}  // namespace dgwarp
