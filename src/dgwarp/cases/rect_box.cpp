#include "dgwarp/cases/rect_box.hpp"

#include <array>
#include <cmath>

#include "dgwarp/core/error.hpp"

namespace dgwarp {

namespace {

// The point at arc-length fraction u in [0, 1) along the perimeter of the
// rectangle [-a, a] × [-b, b], counter-clockwise from (-a, -b). Corner k sits at
// fraction c[k] of the parameter, so that the rectangle and the box, walked with
// the same corner fractions, pair their corners.
std::array<double, 2> perimeter_point(double u, double a, double b, const std::array<double, 5>& c) {
    const std::array<std::array<double, 2>, 5> corner = {{{-a, -b}, {a, -b}, {a, b}, {-a, b}, {-a, -b}}};
    int k = 0;
    while (k < 3 && u >= c[k + 1]) ++k;
    const double t = (u - c[k]) / (c[k + 1] - c[k]);
    return {corner[k][0] + t * (corner[k + 1][0] - corner[k][0]),
            corner[k][1] + t * (corner[k + 1][1] - corner[k][1])};
}

}  // namespace

Mesh make_rect_box(const RectBoxOptions& o) {
    const double a = o.rect_width / 2, b = o.rect_height / 2, h = o.box_half_size;
    if (!(a > 0 && b > 0 && h > a && h > b) || o.layers < 2 || o.around < 4 || !(o.growth > 0))
        throw MeshError("rect-box: the rectangle must be non-empty and inside the box, with at least 2 layers");
    const double perimeter = 4 * (a + b);
    const std::array<double, 5> corners = {0, 2 * a / perimeter, (2 * a + 2 * b) / perimeter,
                                           (4 * a + 2 * b) / perimeter, 1};
    for (double c : corners) {
        const double k = c * o.around;
        if (std::abs(k - std::round(k)) > 1e-9)
            throw MeshError("rect-box: " + std::to_string(o.around) +
                            " nodes around do not place every rectangle corner on a node");
    }

    Mesh mesh;
    mesh.dim = 2;
    const int n = o.around, m = o.layers;
    mesh.points.reserve(static_cast<std::size_t>(n) * m * 2);
    // Layer j sits at fraction s_j of the way from the rectangle to the box,
    // with thicknesses growing geometrically.
    for (int j = 0; j < m; ++j) {
        const double s = o.growth == 1.0 ? double(j) / (m - 1)
                                         : (std::pow(o.growth, j) - 1) / (std::pow(o.growth, m - 1) - 1);
        for (int i = 0; i < n; ++i) {
            const double u = double(i) / n;
            const auto inner = perimeter_point(u, a, b, corners);
            const auto outer = perimeter_point(u, h, h, corners);
            mesh.points.push_back((1 - s) * inner[0] + s * outer[0]);
            mesh.points.push_back((1 - s) * inner[1] + s * outer[1]);
        }
    }
    auto id = [n](int i, int j) { return static_cast<NodeId>(j * n + (i % n)); };
    mesh.cells.reserve(static_cast<std::size_t>(n) * (m - 1), 4);
    for (int j = 0; j + 1 < m; ++j)
        for (int i = 0; i < n; ++i) {
            // i runs counter-clockwise and j outwards; outward-then-along,
            // (i, j) -> (i, j+1) -> (i+1, j+1) -> (i+1, j), turns counter-clockwise.
            const NodeId q[] = {id(i, j), id(i, j + 1), id(i + 1, j + 1), id(i + 1, j)};
            mesh.cells.push_back(CellType::quadrilateral, q);
        }
    Marker rect{"rectangle", {}}, farfield{"farfield", {}};
    for (int i = 0; i < n; ++i) {
        const NodeId e[] = {id(i, 0), id(i + 1, 0)};
        rect.elements.push_back(CellType::line, e);
        const NodeId f[] = {id(i, m - 1), id(i + 1, m - 1)};
        farfield.elements.push_back(CellType::line, f);
    }
    mesh.markers = {std::move(rect), std::move(farfield)};
    return mesh;
}

}  // namespace dgwarp
