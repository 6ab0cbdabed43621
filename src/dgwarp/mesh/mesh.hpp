#pragma once
// The neutral mesh: plain data that every format reads into and writes from and
// every algorithm works on.
//
// Conventions, everywhere in dgwarp:
//  - node ids are 0-based `NodeId` (int32);
//  - point arrays are row-major, num_points × dim (dim = 2 or 3);
//  - cells keep the order of the file they came from, so cell i of a report is
//    cell i of the user's file.
#include <array>
#include <cstdint>
#include <iterator>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "dgwarp/mesh/cell_type.hpp"

namespace dgwarp {

using NodeId = std::int32_t;

/// Elements of mixed types in one list (compressed rows): element i has type
/// types[i] and nodes nodes[offsets[i] .. offsets[i+1]).
///
/// A polygon's nodes go round it in order (counter-clockwise for a 2D cell
/// written so). A polyhedron's nodes are its distinct nodes (in the order its
/// faces first name them), and its faces are kept beside them: faces_of(i)
/// are face ids f, each a ring face_nodes_of(f) whose normal (right-hand rule)
/// points out of the cell. The face arrays stay empty while the list holds no
/// polyhedron, so other meshes pay nothing for them.
struct ElementList {
    std::vector<CellType> types;
    std::vector<std::int64_t> offsets{0};  // size() + 1 entries
    std::vector<NodeId> nodes;
    std::vector<std::int64_t> face_first;      // empty, or size() + 1 entries: element i's faces [face_first[i], face_first[i+1])
    std::vector<std::int64_t> face_offsets{0};  // face f's nodes: face_nodes[face_offsets[f] .. face_offsets[f+1])
    std::vector<NodeId> face_nodes;

    std::size_t size() const { return types.size(); }
    bool empty() const { return types.empty(); }
    std::span<const NodeId> nodes_of(std::size_t i) const {
        return {nodes.data() + offsets[i], static_cast<std::size_t>(offsets[i + 1] - offsets[i])};
    }
    /// Whether any element is a polyhedron (the face arrays are in use).
    bool has_faces() const { return !face_first.empty(); }
    /// The face ids of element i (none but a polyhedron's).
    std::pair<std::int64_t, std::int64_t> faces_of(std::size_t i) const {
        if (face_first.empty()) return {0, 0};
        return {face_first[i], face_first[i + 1]};
    }
    std::span<const NodeId> face_nodes_of(std::int64_t f) const {
        const auto k = static_cast<std::size_t>(f);
        return {face_nodes.data() + face_offsets[k], static_cast<std::size_t>(face_offsets[k + 1] - face_offsets[k])};
    }
    /// Appends an element; `element_nodes` must hold nodes_per_cell(type) ids
    /// (a polygon: 3 or more). Not for polyhedra: push_polyhedron.
    void push_back(CellType type, std::span<const NodeId> element_nodes);
    /// Appends a polyhedron of face_sizes.size() faces, their rings one after
    /// another in `rings` (normals out of the cell); its nodes are the
    /// distinct ids of the rings in the order they first appear.
    void push_polyhedron(std::span<const NodeId> rings, std::span<const int> face_sizes);
    /// Reserves room for n elements of up to nodes_per_element nodes each.
    void reserve(std::size_t n, int nodes_per_element);
    /// Removes every element; the arrays keep their capacity.
    void clear();

    bool operator==(const ElementList&) const = default;
};

/// Calls f(NodeId&) on every node id the list holds (its elements' and its
/// polyhedra's faces'): for code that renumbers nodes.
template <class F>
void for_each_node_id(ElementList& list, F&& f) {
    for (NodeId& n : list.nodes) f(n);
    for (NodeId& n : list.face_nodes) f(n);
}

/// Appends element i of `from` (of any type, a polyhedron with its faces) to `to`.
void copy_element(const ElementList& from, std::size_t i, ElementList& to);

/// A named boundary marker and its boundary elements (lines in 2D, triangles
/// and quadrilaterals in 3D).
struct Marker {
    std::string name;
    ElementList elements;

    bool operator==(const Marker&) const = default;
};

struct Mesh {
    int dim = 3;                  // 2 or 3
    std::vector<double> points;   // num_points() × dim, row-major
    ElementList cells;            // volume cells (2D: triangles and quads)
    std::vector<Marker> markers;  // boundary markers, in file order

    std::size_t num_points() const { return points.size() / static_cast<std::size_t>(dim); }
    bool operator==(const Mesh&) const = default;
};

/// The sorted, duplicate-free node ids of a marker's elements.
std::vector<NodeId> marker_nodes(const Marker& marker);

/// The marker called `name`; throws MeshError naming the marker and listing
/// the markers the mesh has when there is none.
const Marker& find_marker(const Mesh& mesh, std::string_view name);

/// How many elements of each type `list` holds, indexed by CellType.
std::array<std::int64_t, std::size(all_cell_types)> count_by_type(const ElementList& list);

/// The coordinates of `nodes` (ids into `points`, num_points × dim), in that
/// order, in one compact nodes.size() × dim array: for loops that read the
/// same few points again and again (they then stay in cache).
std::vector<double> gather_points(int dim, std::span<const double> points, std::span<const NodeId> nodes);

/// Axis-aligned bounding box of the points: min and max per coordinate
/// (dim entries used); both empty-safe (zeros for a mesh without points).
struct BoundingBox {
    std::array<double, 3> min{};
    std::array<double, 3> max{};
};
BoundingBox bounding_box(const Mesh& mesh);
/// The bounding box of `nodes` (ids into `points`, num_points × dim); zeros when empty.
BoundingBox bounding_box(int dim, std::span<const double> points, std::span<const NodeId> nodes);

/// Checks the mesh is consistent: dim is 2 or 3, the point array is a whole
/// number of points, there is at least one cell, every node id is in range, cells have the mesh's
/// dimension and boundary elements one less, and no two markers share a name.
/// Throws MeshError naming the first bad cell, marker element or marker.
void validate(const Mesh& mesh);

/// Throws MeshError naming the first polygon or polyhedron among the cells
/// and the markers' elements, for a format that has neither (`format`, e.g.
/// "SU2"), and the formats that do.
void check_fixed_cell_types(const Mesh& mesh, std::string_view format);

/// The same for a point cloud: no cells, markers of any boundary elements or
/// of single nodes (vertex elements, in 2D and 3D). Methods that need no
/// cells deform it (all but laplacian); nothing measures its quality.
void validate_point_cloud(const Mesh& mesh);

}  // namespace dgwarp
