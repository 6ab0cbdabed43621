#pragma once
// A 2D case stored as 3D, as OpenFOAM stores them: one layer of cells
// between two planes whose faces are the markers `plane_markers`: two
// parallel planes (OpenFOAM's `empty` patches: a planar case) or two planes
// meeting at an axis (its `wedge` patches: an axisymmetric case, the cells at
// the axis prisms with an edge on it). It is deformed as the 2D mesh it is
// (docs/OPENFOAM.md "2D and axisymmetric cases"): the cells' faces on the
// first plane are the 2D cells (triangles, quadrilaterals, and the polygons of
// a polyhedral layer: polyDualMesh's, snappyHexMesh's 2D cases), each other marker's faces give it their edges
// on that plane, and every node of the second plane moves as its twin on the
// first (the node a cell edge across the layer joins it to), in its own
// plane: the planes stay planes and the twins stay twins.
//
// Parallel planes: the first is the one of lower coordinate along their
// normal n. 2D coordinates: when n is a coordinate axis k (the usual case),
// the two other coordinates (k+1, k+2 modulo 3, a right-handed pair about
// +n), taken as they are; otherwise (x - o)·u and (x - o)·v for an
// orthonormal u, v with u × v = n and o a node of the first plane.
// A wedge: the first plane is the first plane marker's; u is along the axis
// and v in the first plane away from it (o on the axis): 2D coordinates are
// axial and radial; a node of the second plane is lifted with its own plane's
// radial direction. The nodes on the axis are on both planes; the 2D mesh's
// edges on the axis are a marker (`axis_marker`) that slides along it.
//
// 2D cell i is 3D cell i (its face on the first plane, counter-clockwise
// about the first plane's normal into the mesh); 2D node j is the j-th node
// of the first plane (the axis included) in 3D node order.
#include <array>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "dgwarp/mesh/mesh.hpp"

namespace dgwarp {

struct PlanarCase {
    Mesh mesh;                       // the 2D mesh (dim 2); its markers: the 3D mesh's others, in order
    std::vector<NodeId> node_3d;     // per 2D node: the 3D node it is
    std::vector<NodeId> node_2d;     // per 3D node: its 2D node (itself, or its twin's on the first plane)
    std::vector<std::uint8_t> side;  // per 3D node: 1 on the first plane, 2 on the second, 3 on both (a wedge's axis)
    bool wedge = false;              // planes meeting at an axis (else parallel)
    int axis = -1;                   // parallel planes normal to a coordinate axis: it; else -1
    /// Unit normals of the first and second plane (into the mesh from the
    /// first); the in-plane directions u (a wedge: along its axis), v of the
    /// first plane and v_second of the second; o.
    std::array<double, 3> normal{}, normal_second{}, u{}, v{}, v_second{}, origin{};
    double thickness = 0;  // the distance between parallel planes; a wedge: its angle (radians)
    std::vector<std::string> plane_markers;  // their names (not markers of the 2D mesh)
    std::string axis_marker;                 // a wedge: the 2D marker of the edges on the axis
};

/// The planar case of `mesh`, or the reason it is not one.
struct PlanarCaseResult {
    std::optional<PlanarCase> planar;
    std::string not_planar;  // why not (naming the cell, node or marker), when planar is empty
};

/// Whether the 3D `mesh` is one cell thick between the planes of the faces
/// of `plane_markers` (indices into mesh.markers; at least one), and its 2D
/// mesh when it is. A wedge's axis edges become the 2D marker `axis_name`
/// (the 3D marker of that name, if any, has no faces: OpenFOAM's `axis`
/// patch). Not one: faces of those markers on more or fewer than two planes
/// (parallel, or two markers meeting at an axis; nodes within 1e-6 of the
/// bounding-box diagonal of their plane), a node on neither, a cell other
/// than a hexahedron, prism or polyhedron or without a face on the first
/// plane, an edge joining a node of the second plane to two of the first, or a face
/// of another marker without exactly one edge on the first plane.
PlanarCaseResult find_planar_case(const Mesh& mesh, std::span<const std::size_t> plane_markers,
                                  const std::string& axis_name = "axis");

/// The 2D coordinates of a 3D point of the first plane (`second`: of the
/// second plane, in its own directions).
std::array<double, 2> planar_point(const PlanarCase& planar, const std::array<double, 3>& x, bool second = false);

/// The 2D components of a 3D vector at a node of the first plane (`second`:
/// of the second); `along_normal` gets its component along that plane's normal.
std::array<double, 2> planar_vector(const PlanarCase& planar, const std::array<double, 3>& d, bool second = false,
                                    double* along_normal = nullptr);

/// The 3D points (num 3D points × 3) of the mesh whose 2D mesh has moved to
/// `points_2d`: each 3D node of `original` (the 3D mesh's points) moves by its
/// 2D node's displacement, in the planes. A coordinate the node shares with
/// its 2D node (every in-plane coordinate when the normal is a coordinate
/// axis) is its 2D node's new one, bit for bit: twins stay aligned exactly.
void lift_points(const PlanarCase& planar, std::span<const double> original, std::span<const double> points_2d,
                 std::span<double> out);

}  // namespace dgwarp
