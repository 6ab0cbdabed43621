#pragma once
// The signed area of a 2D cell, for tests of 2D generators.
#include <cstddef>

#include "dgwarp/mesh/mesh.hpp"

namespace dgwarp::test {

/// Shoelace area of cell `cell` of the 2D mesh `m` (positive when counter-clockwise).
inline double signed_area(const Mesh& m, std::size_t cell) {
    const auto n = m.cells.nodes_of(cell);
    double a = 0;
    for (std::size_t k = 0; k < n.size(); ++k) {
        const NodeId p = n[k], q = n[(k + 1) % n.size()];
        a += m.points[2 * p] * m.points[2 * q + 1] - m.points[2 * q] * m.points[2 * p + 1];
    }
    return a / 2;
}

}  // namespace dgwarp::test
