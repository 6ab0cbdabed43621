#pragma once
// Test elements for the quality tests: the ideal element of each type (VTK
// node order), random perturbations of it, and rigid motions / scalings.
#include <Eigen/Geometry>

#include <cmath>
#include <random>
#include <vector>

#include "dgwarp/mesh/cell_type.hpp"
#include "dgwarp/quality/cell_quality.hpp"

namespace dgwarp::test {

/// One element: its type, dimension and nodes (nodes × dim, row-major).
struct TestElement {
    CellType type;
    int dim;
    std::vector<double> x;

    int nodes() const { return nodes_per_cell(type); }
    double quality(int orientation = 1) const { return cell_shape_quality(type, x, dim, orientation); }
    int orientation() const { return cell_orientation(type, x, dim); }
};

/// The six types with a shape metric.
inline constexpr CellType quality_types[] = {CellType::triangle,   CellType::quadrilateral, CellType::tetrahedron,
                                             CellType::hexahedron, CellType::prism,         CellType::pyramid};

/// The ideal element of `type` (quality 1), unit edges: equilateral triangle,
/// unit square, regular tetrahedron, unit cube, right prism on an equilateral
/// triangle (VTK wedge: (0,1,2) turns clockwise seen from (3,4,5)), pyramid on
/// the unit square with its apex above the centre at height 1/√2.
inline TestElement ideal_element(CellType type) {
    const double s3 = std::sqrt(3.0);
    switch (type) {
        case CellType::triangle: return {type, 2, {0, 0, 1, 0, 0.5, s3 / 2}};
        case CellType::quadrilateral: return {type, 2, {0, 0, 1, 0, 1, 1, 0, 1}};
        case CellType::tetrahedron:
            return {type, 3, {0, 0, 0, 1, 0, 0, 0.5, s3 / 2, 0, 0.5, s3 / 6, std::sqrt(2.0 / 3.0)}};
        case CellType::hexahedron:
            return {type, 3, {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0, 0, 0, 1, 1, 0, 1, 1, 1, 1, 0, 1, 1}};
        case CellType::prism:
            return {type, 3, {0, 0, 0, 0.5, s3 / 2, 0, 1, 0, 0, 0, 0, 1, 0.5, s3 / 2, 1, 1, 0, 1}};
        case CellType::pyramid:
            return {type, 3, {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0, 0.5, 0.5, 1 / std::sqrt(2.0)}};
        default: return {type, 3, {}};
    }
}

/// The ideal element with every coordinate moved by up to ±amplitude.
inline TestElement perturbed(CellType type, std::mt19937& rng, double amplitude) {
    TestElement e = ideal_element(type);
    std::uniform_real_distribution<double> u(-amplitude, amplitude);
    for (double& v : e.x) v += u(rng);
    return e;
}

/// `e` rotated (a random rotation), scaled by `scale` and translated.
inline TestElement moved(const TestElement& e, std::mt19937& rng, double scale) {
    std::uniform_real_distribution<double> u(-1, 1);
    TestElement out = e;
    if (e.dim == 2) {
        const double a = 3.14159 * u(rng), c = std::cos(a), s = std::sin(a);
        const double tx = 10 * u(rng), ty = 10 * u(rng);
        for (int n = 0; n < e.nodes(); ++n) {
            const double x = e.x[2 * n], y = e.x[2 * n + 1];
            out.x[2 * n] = scale * (c * x - s * y) + tx;
            out.x[2 * n + 1] = scale * (s * x + c * y) + ty;
        }
        return out;
    }
    const Eigen::Vector3d axis = Eigen::Vector3d(u(rng), u(rng), u(rng)).normalized();
    const Eigen::Matrix3d r = Eigen::AngleAxisd(3.14159 * u(rng), axis).toRotationMatrix();
    const Eigen::Vector3d t(10 * u(rng), 10 * u(rng), 10 * u(rng));
    for (int n = 0; n < e.nodes(); ++n) {
        const Eigen::Vector3d p = scale * (r * Eigen::Vector3d(e.x[3 * n], e.x[3 * n + 1], e.x[3 * n + 2])) + t;
        for (int c = 0; c < 3; ++c) out.x[3 * n + c] = p[c];
    }
    return out;
}

/// `e` mirrored in the plane x = 0.
inline TestElement mirrored(const TestElement& e) {
    TestElement out = e;
    for (int n = 0; n < e.nodes(); ++n) out.x[n * e.dim] = -out.x[n * e.dim];
    return out;
}

}  // namespace dgwarp::test
