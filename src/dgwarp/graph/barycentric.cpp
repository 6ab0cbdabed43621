#include "dgwarp/graph/barycentric.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace dgwarp {

namespace {

// Signed area (2D) / six times the signed volume (3D) of the simplex q[0..dim].
template <int Dim>
double signed_measure(const double (&q)[Dim + 1][Dim]) {
    if constexpr (Dim == 2) {
        return (q[1][0] - q[0][0]) * (q[2][1] - q[0][1]) - (q[1][1] - q[0][1]) * (q[2][0] - q[0][0]);
    } else {
        double a[3], b[3], c[3];
        for (int d = 0; d < 3; ++d) {
            a[d] = q[1][d] - q[0][d];
            b[d] = q[2][d] - q[0][d];
            c[d] = q[3][d] - q[0][d];
        }
        return a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0]) +
               a[2] * (b[0] * c[1] - b[1] * c[0]);
    }
}

double dot(const double* a, const double* b, int dim) {
    double s = 0;
    for (int d = 0; d < dim; ++d) s += a[d] * b[d];
    return s;
}

/// The corners i, j of `rel` (corners relative to x) as a segment: x's
/// projection on it, clamped to it; e[i] + e[j] = 1.
void segment_coordinates(int dim, const double (*rel)[3], int i, int j, double* e) {
    double ab[3];
    for (int d = 0; d < dim; ++d) ab[d] = rel[j][d] - rel[i][d];
    const double len2 = dot(ab, ab, dim);
    // x = a + t (b - a): t = (x - a).(b - a) / |b - a|^2, x - a = -rel[i].
    double t = len2 > 0 ? -dot(rel[i], ab, dim) / len2 : 0.0;
    t = t < 0 ? 0 : (t > 1 ? 1 : t);
    e[i] = 1 - t;
    e[j] = t;
}

/// The corners i, j, k (3D) as a triangle: barycentrics of x's projection on
/// its plane; false when the triangle has no area.
bool triangle_coordinates(const double (*rel)[3], int i, int j, int k, double* e) {
    const auto cross = [](const double* a, const double* b, double* c) {
        c[0] = a[1] * b[2] - a[2] * b[1];
        c[1] = a[2] * b[0] - a[0] * b[2];
        c[2] = a[0] * b[1] - a[1] * b[0];
    };
    double u[3], v[3], n[3], c[3];
    for (int d = 0; d < 3; ++d) {
        u[d] = rel[j][d] - rel[i][d];
        v[d] = rel[k][d] - rel[i][d];
    }
    cross(u, v, n);
    const double n2 = dot(n, n, 3);
    if (!(n2 > 0)) return false;
    cross(rel[j], rel[k], c);  // (b - x) x (c - x)
    e[i] = dot(c, n, 3) / n2;
    cross(rel[k], rel[i], c);
    e[j] = dot(c, n, 3) / n2;
    e[k] = 1 - e[i] - e[j];
    return true;
}

/// A degenerate simplex (no area or volume: its corners on a line or a plane,
/// as a Delaunay graph of points on a lattice has them): x's coordinates in
/// the facet, then the edge, that holds it best (the largest smallest
/// coordinate), the other corners 0. Finite for any corners; e sums to 1.
void degenerate_coordinates(int dim, const double (*rel)[3], double* e) {
    double best[4] = {0, 0, 0, 0};
    double best_min = -std::numeric_limits<double>::infinity();
    bool found = false;
    if (dim == 3) {
        for (int skip = 0; skip < 4; ++skip) {
            int c[3], n = 0;
            for (int k = 0; k < 4; ++k)
                if (k != skip) c[n++] = k;
            double f[4] = {0, 0, 0, 0};
            if (!triangle_coordinates(rel, c[0], c[1], c[2], f)) continue;
            const double m = std::min({f[c[0]], f[c[1]], f[c[2]]});
            if (std::isfinite(m) && m > best_min) {
                best_min = m;
                std::copy(f, f + 4, best);
                found = true;
            }
        }
    }
    if (!found) {  // every facet flat too (or 2D): the edges
        for (int i = 0; i <= dim; ++i)
            for (int j = i + 1; j <= dim; ++j) {
                double f[4] = {0, 0, 0, 0};
                segment_coordinates(dim, rel, i, j, f);
                // How far x is from the edge: the smaller, the better.
                double off[3];
                for (int d = 0; d < dim; ++d) off[d] = f[i] * rel[i][d] + f[j] * rel[j][d];
                const double m = -dot(off, off, dim);
                if (m > best_min) {
                    best_min = m;
                    std::copy(f, f + 4, best);
                }
            }
    }
    std::copy(best, best + dim + 1, e);
}

template <int Dim>
void barycentric_in(const double* x, const double* const* corner, double* e) {
    double rel[Dim + 1][Dim];
    for (int k = 0; k <= Dim; ++k)
        for (int d = 0; d < Dim; ++d) rel[k][d] = corner[k][d] - x[d];
    double sum = 0;
    for (int k = 0; k <= Dim; ++k) {
        double q[Dim + 1][Dim];
        for (int j = 0; j <= Dim; ++j)
            for (int d = 0; d < Dim; ++d) q[j][d] = j == k ? 0.0 : rel[j][d];
        e[k] = signed_measure<Dim>(q);
        sum += e[k];
    }
    // A degenerate simplex: its measure is round-off of its edges' scale.
    double scale = 0;
    for (int k = 1; k <= Dim; ++k)
        for (int d = 0; d < Dim; ++d) scale = std::max(scale, std::abs(rel[k][d] - rel[0][d]));
    if (!(std::abs(sum) > 1e-12 * (Dim == 2 ? scale * scale : scale * scale * scale))) {
        double rel3[Dim + 1][3] = {};
        for (int k = 0; k <= Dim; ++k)
            for (int d = 0; d < Dim; ++d) rel3[k][d] = rel[k][d];
        degenerate_coordinates(Dim, rel3, e);
        return;
    }
    const double inv = 1.0 / sum;
    for (int k = 0; k <= Dim; ++k) e[k] *= inv;
}

}  // namespace

void barycentric(int dim, const double* x, const double* const* corner, double* e) {
    if (dim == 2) barycentric_in<2>(x, corner, e);
    else barycentric_in<3>(x, corner, e);
}

}  // namespace dgwarp
