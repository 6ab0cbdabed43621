// The shape metric against independent re-computations on random valid
// elements: simplices from edge lengths only (Heron, Cayley–Menger), the
// corner-based elements with Eigen matrices, each corner's edges found from
// the element's edge list (so the library's corner tables are not reused).
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <random>
#include <utility>
#include <vector>

#include "dgwarp/quality/cell_quality.hpp"
#include "quality/quality_test_elements.hpp"

using namespace dgwarp;
using dgwarp::test::TestElement;

namespace {

Eigen::Vector3d node(const TestElement& e, int n) {
    return {e.x[n * e.dim], e.x[n * e.dim + 1], e.dim == 3 ? e.x[n * e.dim + 2] : 0.0};
}

double squared_edge_sum(const TestElement& e) {
    double s = 0;
    for (int i = 0; i < e.nodes(); ++i)
        for (int j = i + 1; j < e.nodes(); ++j) s += (node(e, j) - node(e, i)).squaredNorm();
    return s;
}

std::vector<std::pair<int, int>> edges_of(CellType type) {
    switch (type) {
        case CellType::quadrilateral: return {{0, 1}, {1, 2}, {2, 3}, {3, 0}};
        case CellType::hexahedron:
            return {{0, 1}, {1, 2}, {2, 3}, {3, 0}, {4, 5}, {5, 6}, {6, 7}, {7, 4}, {0, 4}, {1, 5}, {2, 6}, {3, 7}};
        case CellType::prism: return {{0, 1}, {1, 2}, {2, 0}, {3, 4}, {4, 5}, {5, 3}, {0, 3}, {1, 4}, {2, 5}};
        case CellType::pyramid: return {{0, 1}, {1, 2}, {2, 3}, {3, 0}, {0, 4}, {1, 4}, {2, 4}, {3, 4}};
        default: return {};
    }
}

std::vector<int> neighbours(CellType type, int corner) {
    std::vector<int> out;
    for (auto [a, b] : edges_of(type)) {
        if (a == corner) out.push_back(b);
        if (b == corner) out.push_back(a);
    }
    return out;
}

// Knupp's shape of a weighted corner: T = A W⁻¹, d |det T|^(2/d) / |T|_F².
double corner_shape(const Eigen::MatrixXd& a, const Eigen::MatrixXd& w) {
    const Eigen::MatrixXd t = a * w.inverse();
    const double d = static_cast<double>(a.cols());
    return d * std::pow(std::fabs(t.determinant()), 2.0 / d) / t.squaredNorm();
}

double harmonic_mean(const std::vector<double>& v) {
    double s = 0;
    for (double x : v) s += 1.0 / x;
    return static_cast<double>(v.size()) / s;
}

// ---- the independent formulas ------------------------------------------

double triangle_by_edge_lengths(const TestElement& e) {
    const double a = (node(e, 1) - node(e, 0)).norm(), b = (node(e, 2) - node(e, 1)).norm(),
                 c = (node(e, 0) - node(e, 2)).norm();
    const double s = (a + b + c) / 2;
    const double area = std::sqrt(s * (s - a) * (s - b) * (s - c));  // Heron
    return 4 * std::sqrt(3.0) * area / (a * a + b * b + c * c);
}

double tetrahedron_by_edge_lengths(const TestElement& e) {
    Eigen::Matrix<double, 5, 5> cm;  // Cayley–Menger: 288 V² = det
    cm.setOnes();
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) cm(i + 1, j + 1) = (node(e, i) - node(e, j)).squaredNorm();
    cm(0, 0) = 0;
    const double volume = std::sqrt(cm.determinant() / 288.0);
    return 12 * std::pow(3 * volume, 2.0 / 3.0) / squared_edge_sum(e);  // Knupp's edge-length form
}

double quadrilateral_by_matrices(const TestElement& e) {
    double sum = 0;  // Knupp: f = 8 / Σ_k tr(AᵀA) / det A
    for (int k = 0; k < 4; ++k) {
        const auto nb = neighbours(e.type, k);
        Eigen::Matrix2d a;
        for (int c = 0; c < 2; ++c) a.col(c) = (node(e, nb[c]) - node(e, k)).head<2>();
        sum += (a.transpose() * a).trace() / std::fabs(a.determinant());
    }
    return 8 / sum;
}

double hexahedron_by_matrices(const TestElement& e) {
    double sum = 0;  // Knupp: f = 24 / Σ_k tr(AᵀA) / det(A)^(2/3)
    for (int k = 0; k < 8; ++k) {
        const auto nb = neighbours(e.type, k);
        Eigen::Matrix3d a;
        for (int c = 0; c < 3; ++c) a.col(c) = node(e, nb[c]) - node(e, k);
        sum += (a.transpose() * a).trace() / std::pow(std::fabs(a.determinant()), 2.0 / 3.0);
    }
    return 24 / sum;
}

double prism_by_matrices(const TestElement& e) {
    Eigen::Matrix3d w;  // ideal corner: two unit edges at 60°, one unit edge normal to them
    w.col(0) = Eigen::Vector3d(1, 0, 0);
    w.col(1) = Eigen::Vector3d(0.5, std::sqrt(3.0) / 2, 0);
    w.col(2) = Eigen::Vector3d(0, 0, 1);
    std::vector<double> corners;
    for (int k = 0; k < 6; ++k) {
        auto nb = neighbours(e.type, k);  // the edge between the triangles goes last
        std::stable_partition(nb.begin(), nb.end(), [&](int n) { return std::abs(n - k) != 3; });
        Eigen::Matrix3d a;
        for (int c = 0; c < 3; ++c) a.col(c) = node(e, nb[c]) - node(e, k);
        corners.push_back(corner_shape(a, w));
    }
    return harmonic_mean(corners);
}

double pyramid_by_matrices(const TestElement& e) {
    Eigen::Matrix3d w;  // ideal corner: two orthogonal unit edges, a unit edge at 60° to both
    w.col(0) = Eigen::Vector3d(1, 0, 0);
    w.col(1) = Eigen::Vector3d(0, 1, 0);
    w.col(2) = Eigen::Vector3d(0.5, 0.5, 1 / std::sqrt(2.0));
    std::vector<double> corners;
    for (int k = 0; k < 4; ++k) {  // base corners: the two base edges, then the edge to the apex
        auto nb = neighbours(e.type, k);
        std::stable_partition(nb.begin(), nb.end(), [](int n) { return n != 4; });
        Eigen::Matrix3d a;
        for (int c = 0; c < 3; ++c) a.col(c) = node(e, nb[c]) - node(e, k);
        corners.push_back(corner_shape(a, w));
    }
    for (int left_out = 0; left_out < 4; ++left_out) {
        // apex sub-corner: three of its four edges; the middle one (the base
        // node opposite the left-out one) plays the 60° edge.
        const int middle = (left_out + 2) % 4;
        Eigen::Matrix3d a;
        a.col(0) = node(e, (left_out + 1) % 4) - node(e, 4);
        a.col(1) = node(e, (left_out + 3) % 4) - node(e, 4);
        a.col(2) = node(e, middle) - node(e, 4);
        corners.push_back(corner_shape(a, w));
    }
    return harmonic_mean(corners);
}

double brute_force(const TestElement& e) {
    switch (e.type) {
        case CellType::triangle: return triangle_by_edge_lengths(e);
        case CellType::tetrahedron: return tetrahedron_by_edge_lengths(e);
        case CellType::quadrilateral: return quadrilateral_by_matrices(e);
        case CellType::hexahedron: return hexahedron_by_matrices(e);
        case CellType::prism: return prism_by_matrices(e);
        case CellType::pyramid: return pyramid_by_matrices(e);
        default: return 0;
    }
}

}  // namespace

TEST(QualityBruteForce, RandomValidElementsMatchTheIndependentFormulas) {
    std::mt19937 rng(2024);
    for (CellType type : test::quality_types) {
        SCOPED_TRACE(std::string(cell_type_name(type)));
        double lowest = 1;
        for (int trial = 0; trial < 300; ++trial) {
            const TestElement e = test::moved(test::perturbed(type, rng, 0.25), rng, 3.0);
            const double value = e.quality(e.orientation());
            ASSERT_GT(value, 0) << "trial " << trial;
            EXPECT_NEAR(value, brute_force(e), 1e-12) << "trial " << trial;
            lowest = std::min(lowest, value);
        }
        EXPECT_LT(lowest, 0.9);  // the sample reaches well away from the ideal
    }
}

TEST(QualityBruteForce, IndependentFormulasGiveTheReferenceValues) {
    // The re-computations themselves reproduce METHODS.md, so they are not vacuous.
    for (CellType type : test::quality_types) EXPECT_NEAR(brute_force(test::ideal_element(type)), 1.0, 1e-12);
    EXPECT_NEAR(brute_force({CellType::quadrilateral, 2, {0, 0, 2, 0, 1.5, 1, 0.5, 1}}), 32.0 / 39.0, 1e-12);
    EXPECT_NEAR(brute_force({CellType::tetrahedron, 3, {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1}}),
                3 * std::cbrt(2.0) / 4.5, 1e-12);
}
