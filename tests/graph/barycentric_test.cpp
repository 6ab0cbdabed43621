#include "dgwarp/graph/barycentric.hpp"

#include <gtest/gtest.h>

#include <cmath>

using namespace dgwarp;

namespace {

// x reproduced from the coordinates, and their sum.
void expect_reproduces(int dim, const double* x, const double* const* c, const double* e) {
    double sum = 0;
    for (int k = 0; k <= dim; ++k) {
        EXPECT_TRUE(std::isfinite(e[k])) << "corner " << k;
        sum += e[k];
    }
    EXPECT_NEAR(sum, 1.0, 1e-14);
    for (int d = 0; d < dim; ++d) {
        double v = 0;
        for (int k = 0; k <= dim; ++k) v += e[k] * c[k][d];
        EXPECT_NEAR(v, x[d], 1e-14) << "coordinate " << d;
    }
}

}  // namespace

TEST(Barycentric, VolumeRatiosOfAProperTetrahedron) {
    const double a[3] = {0, 0, 0}, b[3] = {1, 0, 0}, c[3] = {0, 1, 0}, d[3] = {0, 0, 1};
    const double* corners[4] = {a, b, c, d};
    const double x[3] = {0.1, 0.2, 0.3};
    double e[4];
    barycentric(3, x, corners, e);
    EXPECT_NEAR(e[0], 0.4, 1e-15);  // 1 - 0.1 - 0.2 - 0.3
    EXPECT_NEAR(e[1], 0.1, 1e-15);
    EXPECT_NEAR(e[2], 0.2, 1e-15);
    EXPECT_NEAR(e[3], 0.3, 1e-15);
}

TEST(Barycentric, AFlatTetrahedronGivesTheCoordinatesInTheFacetHoldingThePoint) {
    // Four corners of a unit square (a Delaunay graph of lattice points has such
    // slivers), the point inside the square: the ratios would be 0/0.
    const double a[3] = {0, 0, 0}, b[3] = {1, 0, 0}, c[3] = {1, 1, 0}, d[3] = {0, 1, 0};
    const double* corners[4] = {a, b, c, d};
    const double x[3] = {0.7, 0.2, 0};
    double e[4];
    barycentric(3, x, corners, e);
    expect_reproduces(3, x, corners, e);
    for (double v : e) EXPECT_GE(v, -1e-15);  // inside a facet: no negative coordinate
    // x is in the facets (a, b, c) (coordinates 0.3, 0.5, 0.2) and (a, b, d) (0.1, 0.7,
    // 0.2); the best holds it with the largest smallest coordinate: (a, b, c).
    EXPECT_NEAR(e[0], 0.3, 1e-15);
    EXPECT_NEAR(e[1], 0.5, 1e-15);
    EXPECT_NEAR(e[2], 0.2, 1e-15);
    EXPECT_EQ(e[3], 0.0);
}

TEST(Barycentric, CollinearCornersGiveTheCoordinatesOnAnEdge) {
    const double a[2] = {0, 0}, b[2] = {1, 0}, c[2] = {2, 0};
    const double* corners[3] = {a, b, c};
    const double x[2] = {1.5, 0};
    double e[3];
    barycentric(2, x, corners, e);
    expect_reproduces(2, x, corners, e);
    const double a3[3] = {0, 0, 0}, b3[3] = {1, 1, 1}, c3[3] = {2, 2, 2}, d3[3] = {3, 3, 3};
    const double* line[4] = {a3, b3, c3, d3};
    const double x3[3] = {2.5, 2.5, 2.5};
    double e3[4];
    barycentric(3, x3, line, e3);
    expect_reproduces(3, x3, line, e3);
}
