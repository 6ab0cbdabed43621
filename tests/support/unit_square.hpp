#pragma once
// The smallest 2D mesh: the unit square as two triangles (0 1 2, 0 2 3), with
// the marker "wall" on its bottom and right edges.
#include "dgwarp/mesh/mesh.hpp"

namespace dgwarp::test {

inline Mesh unit_square_two_triangles() {
    Mesh m;
    m.dim = 2;
    m.points = {0, 0, 1, 0, 1, 1, 0, 1};
    const NodeId t0[] = {0, 1, 2}, t1[] = {0, 2, 3};
    m.cells.push_back(CellType::triangle, t0);
    m.cells.push_back(CellType::triangle, t1);
    Marker wall{"wall", {}};
    const NodeId e0[] = {0, 1}, e1[] = {1, 2};
    wall.elements.push_back(CellType::line, e0);
    wall.elements.push_back(CellType::line, e1);
    m.markers.push_back(wall);
    return m;
}

}  // namespace dgwarp::test
