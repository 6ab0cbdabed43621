#pragma once
// Shared by the Gmsh reader and writer tests: small meshes with every element
// type, a VTK-orientation measure, and a Gmsh library session.
#include <gmsh.h>
#include <gtest/gtest.h>

#include <array>
#include <cstddef>
#include <map>
#include <string>
#include <vector>

#include "dgwarp/mesh/mesh.hpp"

namespace dgwarp::test {

/// gmsh::initialize (quiet, no configuration files) for the lifetime of the object.
struct GmshSession {
    GmshSession() {
        gmsh::initialize(0, nullptr, false);
        gmsh::option::setNumber("General.Terminal", 0);
    }
    ~GmshSession() { gmsh::finalize(); }
    GmshSession(const GmshSession&) = delete;
    GmshSession& operator=(const GmshSession&) = delete;
};

/// Number of nodes of the current Gmsh model.
inline std::size_t gmsh_node_count() {
    std::vector<std::size_t> tags;
    std::vector<double> coord, parametric;
    gmsh::model::mesh::getNodes(tags, coord, parametric, -1, -1, false, false);
    return tags.size();
}

/// Number of elements of dimension `dim` of the current Gmsh model, by Gmsh type id.
inline std::map<int, std::size_t> gmsh_element_counts(int dim) {
    std::vector<int> types;
    std::vector<std::vector<std::size_t>> tags, nodes;
    gmsh::model::mesh::getElements(types, tags, nodes, dim, -1);
    std::map<int, std::size_t> counts;
    for (std::size_t i = 0; i < types.size(); ++i)
        if (!tags[i].empty()) counts[types[i]] = tags[i].size();
    return counts;
}

/// Number of elements in physical group (dim, tag) of the current Gmsh model.
inline std::size_t gmsh_group_size(int dim, int tag) {
    std::vector<int> entities;
    gmsh::model::getEntitiesForPhysicalGroup(dim, tag, entities);
    std::size_t n = 0;
    for (int e : entities) {
        std::vector<int> types;
        std::vector<std::vector<std::size_t>> tags, nodes;
        gmsh::model::mesh::getElements(types, tags, nodes, dim, e);
        for (const auto& t : tags) n += t.size();
    }
    return n;
}

/// det(b - a, c - a, d - a): six times the signed volume of tetrahedron abcd.
inline double orient3d(const double* a, const double* b, const double* c, const double* d) {
    const double u[] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]};
    const double v[] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
    const double w[] = {d[0] - a[0], d[1] - a[1], d[2] - a[2]};
    return u[0] * (v[1] * w[2] - v[2] * w[1]) - u[1] * (v[0] * w[2] - v[2] * w[0]) + u[2] * (v[0] * w[1] - v[1] * w[0]);
}

/// Twice the signed area of triangle abc (2D points).
inline double orient2d(const double* a, const double* b, const double* c) {
    return (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
}

/// Signed measure of the corner of cell i at its node 0, following VTK's
/// conventions: positive for a correctly oriented cell (triangles and quads
/// counter-clockwise; a tetrahedron's face 0-1-2 seen counter-clockwise from
/// node 3; hexahedron and pyramid bases counter-clockwise seen from the top;
/// a wedge's face 0-1-2 clockwise seen from its face 3-4-5).
inline double vtk_corner_orientation(const Mesh& mesh, std::size_t i) {
    const auto n = mesh.cells.nodes_of(i);
    auto p = [&](int k) { return mesh.points.data() + static_cast<std::size_t>(n[k]) * mesh.dim; };
    switch (mesh.cells.types[i]) {
        case CellType::triangle: return orient2d(p(0), p(1), p(2));
        case CellType::quadrilateral: return orient2d(p(0), p(1), p(3));
        case CellType::tetrahedron: return orient3d(p(0), p(1), p(2), p(3));
        case CellType::hexahedron: return orient3d(p(0), p(1), p(3), p(4));
        case CellType::prism: return orient3d(p(0), p(2), p(1), p(3));
        case CellType::pyramid: return orient3d(p(0), p(1), p(3), p(4));
        default: return 0;
    }
}

/// Compares two meshes field by field, so a failure shows what differs
/// (gtest prints a Mesh as raw bytes).
inline void expect_same_mesh(const Mesh& actual, const Mesh& expected) {
    EXPECT_EQ(actual.dim, expected.dim);
    EXPECT_EQ(actual.points, expected.points);
    EXPECT_TRUE(actual.cells.types == expected.cells.types) << "cell types differ";
    EXPECT_EQ(actual.cells.offsets, expected.cells.offsets);
    EXPECT_EQ(actual.cells.nodes, expected.cells.nodes);
    ASSERT_EQ(actual.markers.size(), expected.markers.size());
    for (std::size_t i = 0; i < actual.markers.size(); ++i) {
        EXPECT_EQ(actual.markers[i].name, expected.markers[i].name);
        EXPECT_TRUE(actual.markers[i].elements.types == expected.markers[i].elements.types)
            << "element types of marker " << i << " differ";
        EXPECT_EQ(actual.markers[i].elements.nodes, expected.markers[i].elements.nodes) << "marker " << i;
    }
    EXPECT_TRUE(actual == expected);
}

/// How many cells of each type.
inline std::map<CellType, std::size_t> cell_type_map(const ElementList& list) {
    std::map<CellType, std::size_t> counts;
    for (CellType t : list.types) ++counts[t];
    return counts;
}

/// A small valid MSH 2.2 file: a tetrahedron and a boundary triangle in physical
/// group 5 (line numbers in comments, for the damage tests).
inline const std::string tet_22 =
    "$MeshFormat\n"     // 1
    "2.2 0 8\n"         // 2
    "$EndMeshFormat\n"  // 3
    "$Nodes\n"          // 4
    "4\n"               // 5
    "1 0 0 0\n"         // 6
    "2 1 0 0\n"         // 7
    "3 0 1 0\n"         // 8
    "4 0 0 1\n"         // 9
    "$EndNodes\n"       // 10
    "$Elements\n"       // 11
    "2\n"               // 12
    "1 4 2 1 1 1 2 3 4\n"  // 13
    "2 2 2 5 2 1 3 2\n"    // 14
    "$EndElements\n";      // 15

/// The same mesh in MSH 4.1.
inline const std::string tet_41 =
    "$MeshFormat\n"            // 1
    "4.1 0 8\n"                // 2
    "$EndMeshFormat\n"         // 3
    "$Entities\n"              // 4
    "0 0 1 1\n"                // 5
    "1 0 0 0 1 1 0 1 5 0\n"    // 6
    "1 0 0 0 1 1 1 1 1 0\n"    // 7
    "$EndEntities\n"           // 8
    "$Nodes\n"                 // 9
    "1 4 1 4\n"                // 10
    "3 1 0 4\n"                // 11
    "1\n2\n3\n4\n"             // 12-15
    "0 0 0\n1 0 0\n0 1 0\n0 0 1\n"  // 16-19
    "$EndNodes\n"              // 20
    "$Elements\n"              // 21
    "2 2 1 2\n"                // 22
    "2 1 2 1\n"                // 23
    "1 1 3 2\n"                // 24
    "3 1 4 1\n"                // 25
    "2 1 2 3 4\n"              // 26
    "$EndElements\n";          // 27

/// A 2D mesh of 6 nodes: two triangles and a quadrangle (all counter-clockwise),
/// markers with one shared edge and an empty marker. Coordinates are not
/// short decimals, to exercise exact number output.
inline Mesh mixed_2d_mesh() {
    Mesh m;
    m.dim = 2;
    const double xy[][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}, {2, 0}, {2, 1}};
    for (const auto& p : xy) {
        m.points.push_back(0.1 * p[0] + 1.0 / 3.0);
        m.points.push_back(0.1 * p[1] - 2.0 / 7.0);
    }
    const NodeId t0[] = {0, 1, 2}, q0[] = {1, 4, 5, 2}, t1[] = {0, 2, 3};
    m.cells.push_back(CellType::triangle, t0);
    m.cells.push_back(CellType::quadrilateral, q0);
    m.cells.push_back(CellType::triangle, t1);
    auto marker = [&](std::string name, std::initializer_list<std::array<NodeId, 2>> edges) {
        Marker mk{std::move(name), {}};
        for (const auto& e : edges) mk.elements.push_back(CellType::line, e);
        m.markers.push_back(std::move(mk));
    };
    marker("wall", {{0, 1}, {1, 4}});
    marker("outlet", {{4, 5}});
    marker("top side", {{5, 2}, {2, 3}, {3, 0}});
    marker("corner", {{0, 1}});
    marker("unused", {});
    return m;
}

/// A 3D mesh of one hexahedron, two tetrahedra, a prism and a pyramid (23
/// nodes, all positively oriented in VTK order), with markers mixing
/// triangles and quadrangles, one face in two markers and an empty marker.
inline Mesh mixed_3d_mesh() {
    Mesh m;
    m.dim = 3;
    const double xyz[][3] = {
        {0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1},  // hex 0-7
        {2, 0, 0}, {2, 1, 0}, {3, 0, 0}, {2, 0, 1}, {2, 1, 1}, {3, 0, 1},                      // prism 8-13
        {4, 0, 0}, {5, 0, 0}, {5, 1, 0}, {4, 1, 0}, {4.5, 0.5, 1},                             // pyramid 14-18
        {6, 0, 0}, {7, 0, 0}, {6, 1, 0}, {6, 0, 1}};                                           // tet 19-22
    for (const auto& p : xyz)
        for (int k = 0; k < 3; ++k) m.points.push_back(0.1 * p[k] + (k + 1) / 3.0);
    const NodeId hex[] = {0, 1, 2, 3, 4, 5, 6, 7}, tet[] = {19, 20, 21, 22}, tet2[] = {20, 21, 19, 22},
                 prism[] = {8, 9, 10, 11, 12, 13}, pyramid[] = {14, 15, 16, 17, 18};
    m.cells.push_back(CellType::hexahedron, hex);
    m.cells.push_back(CellType::tetrahedron, tet);
    m.cells.push_back(CellType::tetrahedron, tet2);
    m.cells.push_back(CellType::prism, prism);
    m.cells.push_back(CellType::pyramid, pyramid);

    const NodeId hex_bottom[] = {0, 3, 2, 1}, hex_top[] = {4, 5, 6, 7}, prism_bottom[] = {8, 10, 9},
                 prism_top[] = {11, 12, 13}, pyramid_base[] = {14, 17, 16, 15}, tet_bottom[] = {19, 21, 20},
                 tet_side[] = {19, 20, 22};
    Marker bottom{"bottom", {}}, sides{"far field", {}};
    bottom.elements.push_back(CellType::quadrilateral, hex_bottom);
    bottom.elements.push_back(CellType::triangle, prism_bottom);
    bottom.elements.push_back(CellType::quadrilateral, pyramid_base);
    bottom.elements.push_back(CellType::triangle, tet_bottom);
    sides.elements.push_back(CellType::triangle, prism_top);
    sides.elements.push_back(CellType::quadrilateral, hex_top);
    sides.elements.push_back(CellType::triangle, tet_side);
    sides.elements.push_back(CellType::quadrilateral, hex_bottom);  // also in "bottom"
    m.markers = {bottom, sides, Marker{"unused", {}}};
    return m;
}

}  // namespace dgwarp::test
