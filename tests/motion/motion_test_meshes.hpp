#pragma once
// Small meshes built in code for the motion tests. Motion resolution reads
// only points and markers, so these meshes have no volume cells.
#include <initializer_list>
#include <string>
#include <utility>

#include "dgwarp/mesh/mesh.hpp"

namespace dgwarp::test {

/// A marker of line elements (2D) given as node pairs.
inline Marker line_marker(const std::string& name, std::initializer_list<std::pair<NodeId, NodeId>> lines) {
    Marker m{name, {}};
    for (const auto& [a, b] : lines) {
        const NodeId nodes[] = {a, b};
        m.elements.push_back(CellType::line, nodes);
    }
    return m;
}

/// 2D: a square "airfoil" (nodes 4-7, corners (±0.5, ±0.5)) inside a square
/// "farfield" (nodes 0-3, corners (±2, ±2)); node 8 at (1.2, 0) is a volume node.
inline Mesh two_squares() {
    Mesh m;
    m.dim = 2;
    m.points = {-2, -2, 2, -2, 2, 2, -2, 2, -0.5, -0.5, 0.5, -0.5, 0.5, 0.5, -0.5, 0.5, 1.2, 0};
    m.markers.push_back(line_marker("airfoil", {{4, 5}, {5, 6}, {6, 7}, {7, 4}}));
    m.markers.push_back(line_marker("farfield", {{0, 1}, {1, 2}, {2, 3}, {3, 0}}));
    return m;
}

/// 2D: nodes 0-5 at (i, 0); marker "a" = lines 0-1, 1-2; "b" = 1-2, 2-3;
/// "wall" = 3-4, 4-5. So a and b share nodes 1 and 2, b and wall share node 3.
inline Mesh chain() {
    Mesh m;
    m.dim = 2;
    m.points = {0, 0, 1, 0, 2, 0, 3, 0, 4, 0, 5, 0};
    m.markers.push_back(line_marker("a", {{0, 1}, {1, 2}}));
    m.markers.push_back(line_marker("b", {{1, 2}, {2, 3}}));
    m.markers.push_back(line_marker("wall", {{3, 4}, {4, 5}}));
    return m;
}

/// 3D: the unit cube's corners 0-7 (node i at (i&1, i>>1&1, i>>2&1)); marker
/// "top" = the two triangles of z = 1 (nodes 4-7), "bottom" = those of z = 0
/// (nodes 0-3), "side" = the quad of x = 0 (nodes 0, 2, 6, 4), which shares
/// nodes 4 and 6 with top.
inline Mesh cube_faces() {
    Mesh m;
    m.dim = 3;
    for (int i = 0; i < 8; ++i) m.points.insert(m.points.end(), {double(i & 1), double(i >> 1 & 1), double(i >> 2 & 1)});
    Marker top{"top", {}}, bottom{"bottom", {}}, side{"side", {}};
    const NodeId t0[] = {4, 5, 7}, t1[] = {4, 7, 6}, b0[] = {0, 2, 3}, b1[] = {0, 3, 1}, q[] = {0, 2, 6, 4};
    top.elements.push_back(CellType::triangle, t0);
    top.elements.push_back(CellType::triangle, t1);
    bottom.elements.push_back(CellType::triangle, b0);
    bottom.elements.push_back(CellType::triangle, b1);
    side.elements.push_back(CellType::quadrilateral, q);
    m.markers = {top, bottom, side};
    return m;
}

}  // namespace dgwarp::test
