#pragma once
// A structured box for the sliding tests: an n^dim lattice on [0, 1]^dim with
// quadrilateral (2D) or hexahedral (3D) cells and one marker per face, named
// x_m, x_p, y_m, y_p (, z_m, z_p): the face where that coordinate is 0 or 1.
#include <array>
#include <string>
#include <vector>

#include "dgwarp/mesh/mesh.hpp"

namespace dgwarp::test {

inline Mesh lattice_box(int dim, int n) {
    Mesh m;
    m.dim = dim;
    const int nz = dim == 3 ? n : 1;
    const auto id = [&](int i, int j, int k) { return static_cast<NodeId>(i + n * (j + n * k)); };
    for (int k = 0; k < nz; ++k)
        for (int j = 0; j < n; ++j)
            for (int i = 0; i < n; ++i) {
                m.points.push_back(double(i) / (n - 1));
                m.points.push_back(double(j) / (n - 1));
                if (dim == 3) m.points.push_back(double(k) / (n - 1));
            }
    if (dim == 2) {
        for (int j = 0; j + 1 < n; ++j)
            for (int i = 0; i + 1 < n; ++i) {
                const NodeId q[] = {id(i, j, 0), id(i + 1, j, 0), id(i + 1, j + 1, 0), id(i, j + 1, 0)};
                m.cells.push_back(CellType::quadrilateral, q);
            }
        const char* names[] = {"x_m", "x_p", "y_m", "y_p"};
        for (int f = 0; f < 4; ++f) {
            Marker marker{names[f], {}};
            const int at = f % 2 == 0 ? 0 : n - 1;
            for (int s = 0; s + 1 < n; ++s) {
                const NodeId line[] = {f < 2 ? id(at, s, 0) : id(s, at, 0), f < 2 ? id(at, s + 1, 0) : id(s + 1, at, 0)};
                marker.elements.push_back(CellType::line, line);
            }
            m.markers.push_back(marker);
        }
        return m;
    }
    for (int k = 0; k + 1 < n; ++k)
        for (int j = 0; j + 1 < n; ++j)
            for (int i = 0; i + 1 < n; ++i) {
                const NodeId h[] = {id(i, j, k),     id(i + 1, j, k),     id(i + 1, j + 1, k),     id(i, j + 1, k),
                                    id(i, j, k + 1), id(i + 1, j, k + 1), id(i + 1, j + 1, k + 1), id(i, j + 1, k + 1)};
                m.cells.push_back(CellType::hexahedron, h);
            }
    const char* names[] = {"x_m", "x_p", "y_m", "y_p", "z_m", "z_p"};
    for (int f = 0; f < 6; ++f) {
        Marker marker{names[f], {}};
        const int axis = f / 2, at = f % 2 == 0 ? 0 : n - 1;
        for (int b = 0; b + 1 < n; ++b)
            for (int a = 0; a + 1 < n; ++a) {
                const auto node = [&](int u, int v) {
                    std::array<int, 3> c{};
                    c[axis] = at;
                    c[(axis + 1) % 3] = u;
                    c[(axis + 2) % 3] = v;
                    return id(c[0], c[1], c[2]);
                };
                const NodeId q[] = {node(a, b), node(a + 1, b), node(a + 1, b + 1), node(a, b + 1)};
                marker.elements.push_back(CellType::quadrilateral, q);
            }
        m.markers.push_back(marker);
    }
    return m;
}

}  // namespace dgwarp::test
