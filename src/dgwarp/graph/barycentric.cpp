#include "dgwarp/graph/barycentric.hpp"

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
    const double inv = 1.0 / sum;
    for (int k = 0; k <= Dim; ++k) e[k] *= inv;
}

}  // namespace

void barycentric(int dim, const double* x, const double* const* corner, double* e) {
    if (dim == 2) barycentric_in<2>(x, corner, e);
    else barycentric_in<3>(x, corner, e);
}

}  // namespace dgwarp
