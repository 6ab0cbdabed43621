// Polygons and polyhedra (cell_quality.hpp): Knupp's shape metric on their
// decomposition from centres, each piece measured against the same piece of
// the regular polygon (or of the right prism on it) with the face's number
// of sides. Definitions: docs/QUALITY.md, "Polygons and polyhedra".
#include <algorithm>
#include <array>
#include <cassert>
#include <cmath>
#include <numbers>
#include <vector>

#include "dgwarp/quality/cell_quality.hpp"
#include "dgwarp/quality/corner_jacobian.hpp"

namespace dgwarp {

namespace {

using quality_detail::CornerRatio;
using quality_detail::Point3;
using quality_detail::cross;
using quality_detail::dot;
using quality_detail::minus;

/// The ideal piece of an n-gon: from its centre, two edges to consecutive
/// corners of the regular n-gon of unit side (length R = 1 / (2 sin(π/n)),
/// at 2π/n) and, for a polyhedron's piece, the edge to the cell centre at
/// the apothem's height 1 / (2 tan(π/n)) above the face centre (a cube's
/// pieces, and a square's, are the ideal ones of n = 4). `gram` is
/// (WᵀW)⁻¹ (row-major, the 2×2 or 3×3 block used), `det_scale` 1 / det W.
struct IdealPiece {
    std::array<double, 9> gram{};
    double det_scale = 0;
};

IdealPiece ideal_piece(std::size_t sides, bool solid) {
    const double n = static_cast<double>(sides), phi = 2 * std::numbers::pi / n;
    const double r = 1.0 / (2 * std::sin(std::numbers::pi / n)), h = 1.0 / (2 * std::tan(std::numbers::pi / n));
    // W = [[r, r cos φ, 0], [0, r sin φ, 0], [0, 0, h]]: WᵀW = [[r², r² cos φ, 0], [r² cos φ, r², 0], [0, 0, h²]].
    const double a = r * r, b = r * r * std::cos(phi), det2 = a * a - b * b;
    IdealPiece w;
    w.gram = {a / det2, -b / det2, 0, -b / det2, a / det2, 0, 0, 0, solid ? 1.0 / (h * h) : 0.0};
    w.det_scale = 1.0 / (r * r * std::sin(phi) * (solid ? h : 1.0));
    return w;
}

const IdealPiece& cached_ideal(std::size_t sides, bool solid) {
    // Faces of up to 64 sides from a table, any more computed (and kept per call).
    static const auto table = [] {
        std::array<std::array<IdealPiece, 65>, 2> t{};
        for (int s = 0; s < 2; ++s)
            for (std::size_t k = 3; k < 65; ++k) t[static_cast<std::size_t>(s)][k] = ideal_piece(k, s == 1);
        return t;
    }();
    thread_local IdealPiece other;
    if (sides < 65) return table[solid ? 1 : 0][sides];
    other = ideal_piece(sides, solid);
    return other;
}

/// The points of `ids` (into `points`, n × dim) as 3D points, scaled as the other elements' are.
std::vector<Point3> scaled_points(std::span<const NodeId> ids, int dim, std::span<const double> points) {
    std::vector<double> coords(ids.size() * static_cast<std::size_t>(dim));
    for (std::size_t i = 0; i < ids.size(); ++i)
        for (int k = 0; k < dim; ++k)
            coords[i * static_cast<std::size_t>(dim) + static_cast<std::size_t>(k)] =
                points[static_cast<std::size_t>(ids[i]) * static_cast<std::size_t>(dim) + static_cast<std::size_t>(k)];
    std::vector<Point3> x(ids.size());
    quality_detail::to_scaled_points(coords, dim, x);
    return x;
}

Point3 centre_of(std::span<const Point3> x) {
    Point3 c{0, 0, 0};
    for (const Point3& p : x)
        for (int k = 0; k < 3; ++k) c[k] += p[k];
    for (double& v : c) v /= static_cast<double>(x.size());
    return c;
}

/// The pieces of a polygon x (its corners in order) from its centre: per
/// corner k the triangle (centre, x[k], x[k+1]); α measured in the xy plane
/// (`planar`) or along the polygon's mean normal.
std::vector<CornerRatio> polygon_pieces(std::span<const Point3> x, bool planar, int orientation, double* alpha_sum) {
    const Point3 c = centre_of(x);
    const std::size_t n = x.size();
    Point3 normal{0, 0, 1};
    if (!planar) {
        Point3 sum{0, 0, 0};
        for (std::size_t k = 0; k < n; ++k) {
            const Point3 a = cross(minus(x[k], c), minus(x[(k + 1) % n], c));
            for (int j = 0; j < 3; ++j) sum[j] += a[j];
        }
        const double length = std::sqrt(dot(sum, sum));
        normal = length > 0 ? Point3{sum[0] / length, sum[1] / length, sum[2] / length} : Point3{0, 0, 0};
    }
    const IdealPiece& w = cached_ideal(n, false);
    std::vector<CornerRatio> pieces(n);
    double total = 0;
    for (std::size_t k = 0; k < n; ++k) {
        const Point3 e1 = minus(x[k], c), e2 = minus(x[(k + 1) % n], c);
        const double alpha = dot(cross(e1, e2), normal);
        total += alpha;
        const double l11 = dot(e1, e1), l22 = dot(e2, e2), l12 = dot(e1, e2);
        // 2D corner shape 2 det(T) / |T|_F² with T = A W⁻¹.
        pieces[k] = {2.0 * w.det_scale * (planar ? orientation : 1) * alpha,
                     w.gram[0] * l11 + 2 * w.gram[1] * l12 + w.gram[4] * l22};
    }
    if (alpha_sum) *alpha_sum = total;
    return pieces;
}

/// The pieces of polyhedron i of `list`: per face, per face edge (x[k],
/// x[k+1]) the tetrahedron (face centre, x[k+1], x[k], cell centre), positive
/// for outward faces round a cell centre inside.
std::vector<CornerRatio> polyhedron_pieces(const ElementList& list, std::size_t i, std::span<const double> points,
                                           int orientation, double* alpha_sum) {
    const auto nodes = list.nodes_of(i);
    const std::vector<Point3> x = scaled_points(nodes, 3, points);
    const Point3 c = centre_of(x);
    std::vector<CornerRatio> pieces;
    std::vector<Point3> ring;
    double total = 0;
    const auto [f0, f1] = list.faces_of(i);
    for (std::int64_t f = f0; f < f1; ++f) {
        const auto face = list.face_nodes_of(f);
        ring.clear();
        for (NodeId v : face)
            ring.push_back(x[static_cast<std::size_t>(std::find(nodes.begin(), nodes.end(), v) - nodes.begin())]);
        const Point3 fc = centre_of(ring);
        const IdealPiece& w = cached_ideal(ring.size(), true);
        const Point3 a3 = minus(c, fc);
        for (std::size_t k = 0; k < ring.size(); ++k) {
            const Point3 a1 = minus(ring[(k + 1) % ring.size()], fc), a2 = minus(ring[k], fc);
            const double alpha = dot(a3, cross(a1, a2));
            total += alpha;
            const double l[9] = {dot(a1, a1), dot(a1, a2), dot(a1, a3), dot(a1, a2), dot(a2, a2),
                                 dot(a2, a3), dot(a1, a3), dot(a2, a3), dot(a3, a3)};
            double trace = 0;  // tr(λ G), G symmetric
            for (int r = 0; r < 3; ++r)
                for (int s = 0; s < 3; ++s) trace += l[r * 3 + s] * w.gram[static_cast<std::size_t>(s * 3 + r)];
            pieces.push_back(
                {3.0 * quality_detail::signed_two_thirds(w.det_scale * orientation * alpha), trace});
        }
    }
    if (alpha_sum) *alpha_sum = total;
    return pieces;
}

/// The coordinates of element i (of a fixed type: at most 8 nodes) in `out`, nodes × dim.
std::span<const double> fixed_cell_coords(const ElementList& list, std::size_t i, int dim, std::span<const double> points,
                                          std::array<double, 24>& out) {
    const auto nodes = list.nodes_of(i);
    const auto d = static_cast<std::size_t>(dim);
    for (std::size_t n = 0; n < nodes.size(); ++n)
        for (std::size_t k = 0; k < d; ++k) out[n * d + k] = points[static_cast<std::size_t>(nodes[n]) * d + k];
    return {out.data(), nodes.size() * d};
}

}  // namespace

double element_shape_quality(const ElementList& list, std::size_t i, int dim, std::span<const double> points,
                             int orientation) {
    const CellType type = list.types[i];
    const int sign = orientation < 0 ? -1 : 1;
    if (type == CellType::polygon) {
        const std::vector<Point3> x = scaled_points(list.nodes_of(i), dim, points);
        return quality_detail::combine_corners(polygon_pieces(x, dim == 2, sign, nullptr));
    }
    if (type == CellType::polyhedron) return quality_detail::combine_corners(polyhedron_pieces(list, i, points, sign, nullptr));
    std::array<double, 24> coords;
    return cell_shape_quality(type, fixed_cell_coords(list, i, dim, points, coords), dim, sign);
}

int element_orientation(const ElementList& list, std::size_t i, int dim, std::span<const double> points) {
    const CellType type = list.types[i];
    double measure = 0;
    if (type == CellType::polygon) {
        if (dim != 2) return 1;
        const std::vector<Point3> x = scaled_points(list.nodes_of(i), dim, points);
        polygon_pieces(x, true, 1, &measure);
    } else if (type == CellType::polyhedron) {
        polyhedron_pieces(list, i, points, 1, &measure);
    } else {
        std::array<double, 24> coords;
        return cell_orientation(type, fixed_cell_coords(list, i, dim, points, coords), dim);
    }
    return measure < 0 ? -1 : 1;
}

}  // namespace dgwarp
