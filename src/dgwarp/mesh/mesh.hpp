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
#include <vector>

#include "dgwarp/mesh/cell_type.hpp"

namespace dgwarp {

using NodeId = std::int32_t;

/// Elements of mixed types in one list (compressed rows): element i has type
/// types[i] and nodes nodes[offsets[i] .. offsets[i+1]).
struct ElementList {
    std::vector<CellType> types;
    std::vector<std::int64_t> offsets{0};  // size() + 1 entries
    std::vector<NodeId> nodes;

    std::size_t size() const { return types.size(); }
    bool empty() const { return types.empty(); }
    std::span<const NodeId> nodes_of(std::size_t i) const {
        return {nodes.data() + offsets[i], static_cast<std::size_t>(offsets[i + 1] - offsets[i])};
    }
    /// Appends an element; `element_nodes` must hold nodes_per_cell(type) ids.
    void push_back(CellType type, std::span<const NodeId> element_nodes);
    /// Reserves room for n elements of up to nodes_per_element nodes each.
    void reserve(std::size_t n, int nodes_per_element);

    bool operator==(const ElementList&) const = default;
};

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

/// The same for a point cloud: no cells, markers of any boundary elements or
/// of single nodes (vertex elements, in 2D and 3D). Methods that need no
/// cells deform it (all but laplacian); nothing measures its quality.
void validate_point_cloud(const Mesh& mesh);

}  // namespace dgwarp
