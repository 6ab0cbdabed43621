// A 2D case stored as 3D (mesh/planar_case.hpp): OpenFOAM's cavity (empty
// planes normal to z), the same turned so that its normal is no axis, and a
// wedge made here (an axisymmetric case with prisms at its axis).
#include "dgwarp/mesh/planar_case.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <numbers>

#include "dgwarp/io/mesh_io.hpp"
#include "support/cell_area.hpp"
#include "support/test_paths.hpp"

namespace dgwarp {
namespace {

using P3 = std::array<double, 3>;

Mesh cavity() { return read_mesh(test::source_dir() / "tests/data/openfoam/cavity"); }

std::size_t marker_index(const Mesh& mesh, const std::string& name) {
    for (std::size_t m = 0; m < mesh.markers.size(); ++m)
        if (mesh.markers[m].name == name) return m;
    ADD_FAILURE() << "no marker " << name;
    return 0;
}

P3 point(const Mesh& mesh, std::size_t v) {
    return {mesh.points[3 * v], mesh.points[3 * v + 1], mesh.points[3 * v + 2]};
}

double dot(const P3& a, const P3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

TEST(PlanarCase, TheCavityIsItsFrontPlane) {
    const Mesh mesh = cavity();  // 4 × 3 hexahedra, z from 0 to 0.01
    const std::size_t planes[] = {marker_index(mesh, "frontAndBack")};
    const PlanarCaseResult r = find_planar_case(mesh, planes);
    ASSERT_TRUE(r.planar.has_value()) << r.not_planar;
    const PlanarCase& p = *r.planar;
    EXPECT_FALSE(p.wedge);
    EXPECT_EQ(p.axis, 2);
    EXPECT_EQ(p.normal, (P3{0, 0, 1}));
    EXPECT_NEAR(p.thickness, 0.01, 1e-15);
    EXPECT_EQ(p.mesh.dim, 2);
    EXPECT_EQ(p.mesh.num_points(), 20u);
    ASSERT_EQ(p.mesh.cells.size(), 12u);
    for (std::size_t c = 0; c < 12; ++c) {
        EXPECT_EQ(p.mesh.cells.types[c], CellType::quadrilateral);
        EXPECT_NEAR(test::signed_area(p.mesh, c), 0.025 * 0.1 / 3, 1e-12) << c;  // counter-clockwise
    }
    ASSERT_EQ(p.mesh.markers.size(), 2u);
    EXPECT_EQ(p.mesh.markers[0].name, "movingWall");
    EXPECT_EQ(p.mesh.markers[0].elements.size(), 4u);
    EXPECT_EQ(p.mesh.markers[1].name, "fixedWalls");
    EXPECT_EQ(p.mesh.markers[1].elements.size(), 10u);
    EXPECT_EQ(p.plane_markers, (std::vector<std::string>{"frontAndBack"}));
    // Every 3D node is its 2D node or that node's twin: the same x and y, bit for bit.
    for (std::size_t v = 0; v < mesh.num_points(); ++v) {
        const auto j = static_cast<std::size_t>(p.node_2d[v]);
        EXPECT_EQ(mesh.points[3 * v], p.mesh.points[2 * j]);
        EXPECT_EQ(mesh.points[3 * v + 1], p.mesh.points[2 * j + 1]);
        EXPECT_EQ(p.side[v], mesh.points[3 * v + 2] == 0 ? 1 : 2);
    }
    for (std::size_t j = 0; j < p.node_3d.size(); ++j) EXPECT_EQ(p.node_2d[static_cast<std::size_t>(p.node_3d[j])], static_cast<NodeId>(j));
}

TEST(PlanarCase, LiftingMovesTwinsAlikeInTheirPlanes) {
    const Mesh mesh = cavity();
    const std::size_t planes[] = {marker_index(mesh, "frontAndBack")};
    const PlanarCase p = *find_planar_case(mesh, planes).planar;
    std::vector<double> out(mesh.points.size());
    lift_points(p, mesh.points, p.mesh.points, out);
    EXPECT_EQ(out, mesh.points);  // not moved: the same bits
    std::vector<double> moved = p.mesh.points;
    for (std::size_t j = 0; j < p.node_3d.size(); ++j) {
        moved[2 * j] += 0.001 * static_cast<double>(j % 3);
        moved[2 * j + 1] -= 0.002 * static_cast<double>(j % 5);
    }
    lift_points(p, mesh.points, moved, out);
    for (std::size_t v = 0; v < mesh.num_points(); ++v) {
        const auto j = static_cast<std::size_t>(p.node_2d[v]);
        EXPECT_EQ(out[3 * v], moved[2 * j]);
        EXPECT_EQ(out[3 * v + 1], moved[2 * j + 1]);
        EXPECT_EQ(out[3 * v + 2], mesh.points[3 * v + 2]);
    }
}

/// The cavity turned by `angle` about (1, 2, 3): its planes' normal is no axis.
Mesh turned_cavity(double angle) {
    Mesh mesh = cavity();
    const P3 k = [] {
        const double l = std::sqrt(14.0);
        return P3{1 / l, 2 / l, 3 / l};
    }();
    const double c = std::cos(angle), s = std::sin(angle);
    for (std::size_t v = 0; v < mesh.num_points(); ++v) {
        const P3 x = point(mesh, v);
        const P3 kx{k[1] * x[2] - k[2] * x[1], k[2] * x[0] - k[0] * x[2], k[0] * x[1] - k[1] * x[0]};
        const double kd = dot(k, x);
        for (std::size_t i = 0; i < 3; ++i) mesh.points[3 * v + i] = x[i] * c + kx[i] * s + k[i] * kd * (1 - c);
    }
    return mesh;
}

TEST(PlanarCase, ANormalThatIsNoAxisGivesPlaneCoordinates) {
    const Mesh mesh = turned_cavity(0.7);
    const std::size_t planes[] = {marker_index(mesh, "frontAndBack")};
    const PlanarCaseResult r = find_planar_case(mesh, planes);
    ASSERT_TRUE(r.planar.has_value()) << r.not_planar;
    const PlanarCase& p = *r.planar;
    EXPECT_EQ(p.axis, -1);
    EXPECT_NEAR(p.thickness, 0.01, 1e-12);
    for (std::size_t c = 0; c < p.mesh.cells.size(); ++c)
        EXPECT_NEAR(test::signed_area(p.mesh, c), 0.025 * 0.1 / 3, 1e-12) << c;
    // Lifted, a 2D motion keeps every node in its plane (to round-off) and twins alike.
    std::vector<double> moved = p.mesh.points, out(mesh.points.size());
    for (std::size_t j = 0; j < p.node_3d.size(); ++j) moved[2 * j] += 0.003 * static_cast<double>(j % 4);
    lift_points(p, mesh.points, moved, out);
    for (std::size_t v = 0; v < mesh.num_points(); ++v) {
        const P3 before = point(mesh, v);
        const P3 after{out[3 * v], out[3 * v + 1], out[3 * v + 2]};
        EXPECT_NEAR(dot(p.normal, after), dot(p.normal, before), 1e-16) << v;
        const auto j = static_cast<std::size_t>(p.node_2d[v]);
        const P3 front = point(mesh, static_cast<std::size_t>(p.node_3d[j]));
        for (std::size_t i = 0; i < 3; ++i)  // the twin's displacement is its 2D node's
            EXPECT_NEAR(after[i] - before[i], out[3 * static_cast<std::size_t>(p.node_3d[j]) + i] - front[i], 1e-16);
    }
}

/// A wedge of `angle` about the x axis: 2D quads of an nx × nr grid in
/// (x, r) on [0, 1]², turned by -angle/2 (the first plane, marker "front")
/// and +angle/2 ("back"); nodes at r = 0 are on both; cells at the axis are
/// prisms. Other markers: "inlet" (x = 0), "outlet" (x = 1), "top" (r = 1);
/// "axis" has no faces (OpenFOAM's axis patch).
Mesh wedge(int nx, int nr, double angle) {
    Mesh mesh;
    const auto grid = [&](int i, int k) { return P3{double(i) / nx, double(k) / nr, 0}; };
    std::vector<std::array<NodeId, 2>> node((nx + 1) * (nr + 1));  // front, back
    for (int k = 0; k <= nr; ++k)
        for (int i = 0; i <= nx; ++i) {
            const P3 g = grid(i, k);
            auto& n = node[static_cast<std::size_t>(k * (nx + 1) + i)];
            for (int side = 0; side < 2; ++side) {
                if (k == 0 && side == 1) {
                    n[1] = n[0];
                    continue;
                }
                const double a = (side == 0 ? -0.5 : 0.5) * angle;
                n[static_cast<std::size_t>(side)] = static_cast<NodeId>(mesh.num_points());
                mesh.points.insert(mesh.points.end(), {g[0], g[1] * std::cos(a), g[1] * std::sin(a)});
            }
        }
    const auto at = [&](int i, int k, int side) { return node[static_cast<std::size_t>(k * (nx + 1) + i)][static_cast<std::size_t>(side)]; };
    Marker front{"front", {}}, back{"back", {}}, inlet{"inlet", {}}, outlet{"outlet", {}}, top{"top", {}}, axis{"axis", {}};
    for (int k = 0; k < nr; ++k)
        for (int i = 0; i < nx; ++i) {
            // In (x, r) counter-clockwise: (i,k) (i+1,k) (i+1,k+1) (i,k+1); the front
            // plane is at z < 0: its outward normal is -z-ish, so its face runs clockwise seen from +z.
            const NodeId f[4] = {at(i, k, 0), at(i + 1, k, 0), at(i + 1, k + 1, 0), at(i, k + 1, 0)};
            const NodeId b[4] = {at(i, k, 1), at(i + 1, k, 1), at(i + 1, k + 1, 1), at(i, k + 1, 1)};
            if (k == 0) {
                // A prism: triangles (axis i, front, back) at x_i and x_{i+1}.
                const NodeId prism[6] = {f[0], f[3], b[3], f[1], f[2], b[2]};
                mesh.cells.push_back(CellType::prism, prism);
            } else {
                const NodeId hex[8] = {f[0], f[1], f[2], f[3], b[0], b[1], b[2], b[3]};
                mesh.cells.push_back(CellType::hexahedron, hex);
            }
            const NodeId front_face[4] = {f[0], f[3], f[2], f[1]};  // clockwise about +z: out of the mesh
            const NodeId back_face[4] = {b[0], b[1], b[2], b[3]};
            front.elements.push_back(CellType::quadrilateral, front_face);
            back.elements.push_back(CellType::quadrilateral, back_face);
            if (i == 0) {
                if (k == 0) inlet.elements.push_back(CellType::triangle, std::array<NodeId, 3>{f[0], b[3], f[3]});
                else inlet.elements.push_back(CellType::quadrilateral, std::array<NodeId, 4>{f[0], b[0], b[3], f[3]});
            }
            if (i == nx - 1) {
                if (k == 0) outlet.elements.push_back(CellType::triangle, std::array<NodeId, 3>{f[1], f[2], b[2]});
                else outlet.elements.push_back(CellType::quadrilateral, std::array<NodeId, 4>{f[1], f[2], b[2], b[1]});
            }
            if (k == nr - 1) top.elements.push_back(CellType::quadrilateral, std::array<NodeId, 4>{f[3], f[2], b[2], b[3]});
        }
    mesh.markers = {front, back, inlet, outlet, top, axis};
    return mesh;
}

TEST(PlanarCase, AWedgeIsItsAxialAndRadialPlane) {
    const double angle = 5 * std::numbers::pi / 180;
    const Mesh mesh = wedge(4, 3, angle);
    const std::size_t planes[] = {0, 1};
    const PlanarCaseResult r = find_planar_case(mesh, planes, "axis");
    ASSERT_TRUE(r.planar.has_value()) << r.not_planar;
    const PlanarCase& p = *r.planar;
    EXPECT_TRUE(p.wedge);
    EXPECT_NEAR(p.thickness, angle, 1e-12);
    EXPECT_NEAR(std::abs(p.u[0]), 1, 1e-12);  // along the x axis
    ASSERT_EQ(p.mesh.num_points(), 20u);      // the front's 15 and the axis's 5
    ASSERT_EQ(p.mesh.cells.size(), 12u);
    for (std::size_t c = 0; c < 12; ++c) {
        EXPECT_EQ(p.mesh.cells.types[c], CellType::quadrilateral);
        EXPECT_NEAR(std::abs(test::signed_area(p.mesh, c)), 1.0 / 12, 1e-12) << c;
        EXPECT_GT(test::signed_area(p.mesh, c), 0) << c;
    }
    // 2D coordinates: axial (from the axis's point o) and radial.
    for (std::size_t j = 0; j < p.node_3d.size(); ++j) {
        const P3 x = point(mesh, static_cast<std::size_t>(p.node_3d[j]));
        EXPECT_NEAR(std::abs(p.mesh.points[2 * j + 1]), std::hypot(x[1], x[2]), 1e-12);
        EXPECT_GE(p.mesh.points[2 * j + 1], -1e-12);  // v points away from the axis
    }
    // The axis is a marker of the 4 edges on it; inlet, outlet and top keep an edge per face.
    ASSERT_EQ(p.mesh.markers.size(), 4u);
    EXPECT_EQ(p.axis_marker, "axis");
    EXPECT_EQ(p.mesh.markers[3].name, "axis");
    EXPECT_EQ(p.mesh.markers[3].elements.size(), 4u);
    EXPECT_EQ(p.mesh.markers[0].elements.size(), 3u);
    EXPECT_EQ(p.mesh.markers[2].elements.size(), 4u);

    // Lifted: every node stays in its plane, and a back node is its front twin turned by the angle.
    std::vector<double> moved = p.mesh.points, out(mesh.points.size());
    for (std::size_t j = 0; j < p.node_3d.size(); ++j) {
        moved[2 * j] += 0.01 * static_cast<double>(j % 3);
        if (p.side[static_cast<std::size_t>(p.node_3d[j])] != 3) moved[2 * j + 1] += 0.02 * static_cast<double>(j % 2);
    }
    lift_points(p, mesh.points, moved, out);
    for (std::size_t v = 0; v < mesh.num_points(); ++v) {
        const P3 after{out[3 * v], out[3 * v + 1], out[3 * v + 2]};
        const double turn = (p.side[v] == 2 ? 0.5 : -0.5) * angle;
        if (p.side[v] == 3) {
            EXPECT_NEAR(std::hypot(after[1], after[2]), 0, 1e-15) << v;  // still on the axis
            continue;
        }
        EXPECT_NEAR(-after[1] * std::sin(turn) + after[2] * std::cos(turn), 0, 1e-15) << v;  // in its plane
        const auto j = static_cast<std::size_t>(p.node_2d[v]);
        EXPECT_NEAR(after[0], moved[2 * j] + (mesh.points[3 * v] - p.mesh.points[2 * j]), 1e-15);
        EXPECT_NEAR(std::hypot(after[1], after[2]), moved[2 * j + 1], 1e-15) << v;
    }
}

TEST(PlanarCase, MeshesThatAreNotOneLayerSayWhy) {
    const Mesh mixed = read_mesh(test::source_dir() / "tests/data/openfoam/mixed");
    const std::size_t bottom[] = {marker_index(mixed, "bottom")};
    const PlanarCaseResult r = find_planar_case(mixed, bottom);
    EXPECT_FALSE(r.planar.has_value());
    EXPECT_NE(r.not_planar.find("one plane"), std::string::npos) << r.not_planar;

    // The cavity with its back plane's faces left out: nodes on no plane marker.
    Mesh half = cavity();
    Marker& planes = half.markers[marker_index(half, "frontAndBack")];
    Marker front{planes.name, {}};
    for (std::size_t f = 0; f < planes.elements.size(); ++f)
        if (half.points[3 * static_cast<std::size_t>(planes.elements.nodes_of(f)[0]) + 2] == 0)
            front.elements.push_back(planes.elements.types[f], planes.elements.nodes_of(f));
    planes = front;
    const std::size_t only_front[] = {marker_index(half, "frontAndBack")};
    const PlanarCaseResult h = find_planar_case(half, only_front);
    EXPECT_FALSE(h.planar.has_value());
    EXPECT_NE(h.not_planar.find("one plane"), std::string::npos) << h.not_planar;
}


TEST(PlanarCase, APolyhedralLayerIsItsPolygons) {
    // One layer (z from 0 to 1) of a pentagonal prism given as a polyhedron
    // (nodes 0-4 below, 7-11 above) beside a hexahedron on its edge 0-1
    // (nodes 5, 6 below, 12, 13 above): the 2D mesh is a pentagon and a
    // quadrilateral, counter-clockwise, and the walls' side faces their edges.
    Mesh mesh;
    const double xy[7][2] = {{0, 0}, {1, 0}, {1.3, 0.8}, {0.5, 1.3}, {-0.3, 0.8}, {0, -1}, {1, -1}};
    for (double z : {0.0, 1.0})
        for (const auto& p : xy) mesh.points.insert(mesh.points.end(), {p[0], p[1], z});
    std::vector<NodeId> rings{0, 4, 3, 2, 1, 7, 8, 9, 10, 11};
    std::vector<int> sizes{5, 5};
    for (NodeId a = 0; a < 5; ++a) {
        const NodeId b = (a + 1) % 5;
        rings.insert(rings.end(), {a, b, static_cast<NodeId>(b + 7), static_cast<NodeId>(a + 7)});
        sizes.push_back(4);
    }
    mesh.cells.push_polyhedron(rings, sizes);
    mesh.cells.push_back(CellType::hexahedron, std::array<NodeId, 8>{5, 6, 1, 0, 12, 13, 8, 7});
    Marker front{"front", {}}, back{"back", {}}, walls{"walls", {}};
    front.elements.push_back(CellType::polygon, std::array<NodeId, 5>{0, 4, 3, 2, 1});
    front.elements.push_back(CellType::quadrilateral, std::array<NodeId, 4>{5, 0, 1, 6});
    back.elements.push_back(CellType::polygon, std::array<NodeId, 5>{7, 8, 9, 10, 11});
    back.elements.push_back(CellType::quadrilateral, std::array<NodeId, 4>{12, 13, 8, 7});
    for (const auto& q : {std::array<NodeId, 4>{1, 2, 9, 8}, std::array<NodeId, 4>{2, 3, 10, 9},
                          std::array<NodeId, 4>{3, 4, 11, 10}, std::array<NodeId, 4>{4, 0, 7, 11},
                          std::array<NodeId, 4>{5, 6, 13, 12}, std::array<NodeId, 4>{6, 1, 8, 13},
                          std::array<NodeId, 4>{0, 5, 12, 7}})
        walls.elements.push_back(CellType::quadrilateral, q);
    mesh.markers = {front, back, walls};
    validate(mesh);
    const std::size_t planes[] = {0, 1};
    const PlanarCaseResult r = find_planar_case(mesh, planes);
    ASSERT_TRUE(r.planar.has_value()) << r.not_planar;
    const PlanarCase& p = *r.planar;
    ASSERT_EQ(p.mesh.cells.types, (std::vector<CellType>{CellType::polygon, CellType::quadrilateral}));
    EXPECT_NEAR(test::signed_area(p.mesh, 0), 1.44, 1e-12);  // the pentagon's shoelace area
    EXPECT_NEAR(test::signed_area(p.mesh, 1), 1.0, 1e-12);
    ASSERT_EQ(p.mesh.markers.size(), 1u);
    EXPECT_EQ(p.mesh.markers[0].name, "walls");
    EXPECT_EQ(p.mesh.markers[0].elements.size(), 7u);
    EXPECT_EQ(p.mesh.num_points(), 7u);
    for (std::size_t v = 7; v < 14; ++v) EXPECT_EQ(p.node_2d[v], p.node_2d[v - 7]) << v;  // twins
}

}  // namespace
}  // namespace dgwarp
