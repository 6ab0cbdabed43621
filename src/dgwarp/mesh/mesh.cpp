#include "dgwarp/mesh/mesh.hpp"

#include <algorithm>
#include <cassert>
#include <exception>

#include "dgwarp/core/error.hpp"
#include "dgwarp/core/parallel_for.hpp"

namespace dgwarp {

void ElementList::push_back(CellType type, std::span<const NodeId> element_nodes) {
    assert(type != CellType::polyhedron);
    assert(static_cast<int>(element_nodes.size()) == nodes_per_cell(type) ||
           (type == CellType::polygon && element_nodes.size() >= 3));
    types.push_back(type);
    nodes.insert(nodes.end(), element_nodes.begin(), element_nodes.end());
    offsets.push_back(static_cast<std::int64_t>(nodes.size()));
    if (!face_first.empty()) face_first.push_back(face_first.back());
}

void ElementList::push_polyhedron(std::span<const NodeId> rings, std::span<const int> face_sizes) {
    if (face_first.empty()) face_first.assign(types.size() + 1, 0);
    types.push_back(CellType::polyhedron);
    const std::size_t first = nodes.size();
    std::size_t k = 0;
    for (int size : face_sizes) {
        for (int j = 0; j < size; ++j, ++k) {
            const NodeId n = rings[k];
            face_nodes.push_back(n);
            if (std::find(nodes.begin() + static_cast<std::ptrdiff_t>(first), nodes.end(), n) == nodes.end())
                nodes.push_back(n);
        }
        face_offsets.push_back(static_cast<std::int64_t>(face_nodes.size()));
    }
    offsets.push_back(static_cast<std::int64_t>(nodes.size()));
    face_first.push_back(static_cast<std::int64_t>(face_offsets.size() - 1));
}

void copy_element(const ElementList& from, std::size_t i, ElementList& to) {
    if (from.types[i] != CellType::polyhedron) {
        to.push_back(from.types[i], from.nodes_of(i));
        return;
    }
    const auto [f0, f1] = from.faces_of(i);
    std::vector<int> sizes;
    for (std::int64_t f = f0; f < f1; ++f) sizes.push_back(static_cast<int>(from.face_nodes_of(f).size()));
    const auto begin = from.face_offsets[static_cast<std::size_t>(f0)], end = from.face_offsets[static_cast<std::size_t>(f1)];
    to.push_polyhedron({from.face_nodes.data() + begin, static_cast<std::size_t>(end - begin)}, sizes);
}

void ElementList::reserve(std::size_t n, int nodes_per_element) {
    types.reserve(n);
    offsets.reserve(n + 1);
    nodes.reserve(n * static_cast<std::size_t>(nodes_per_element));
}

void ElementList::clear() {
    types.clear();
    offsets.assign(1, 0);
    nodes.clear();
    face_first.clear();
    face_offsets.assign(1, 0);
    face_nodes.clear();
}

std::vector<NodeId> marker_nodes(const Marker& marker) {
    std::vector<NodeId> ids = marker.elements.nodes;
    std::sort(ids.begin(), ids.end());
    ids.erase(std::unique(ids.begin(), ids.end()), ids.end());
    return ids;
}

const Marker& find_marker(const Mesh& mesh, std::string_view name) {
    for (const Marker& m : mesh.markers)
        if (m.name == name) return m;
    std::string known;
    for (const Marker& m : mesh.markers) known += (known.empty() ? "" : ", ") + m.name;
    throw MeshError("unknown marker '" + std::string(name) + "'; the mesh has: " +
                        (known.empty() ? std::string("no markers") : known),
                    std::string(name));
}

std::array<std::int64_t, std::size(all_cell_types)> count_by_type(const ElementList& list) {
    std::array<std::int64_t, std::size(all_cell_types)> counts{};
    for (CellType t : list.types) ++counts[static_cast<int>(t)];
    return counts;
}

std::vector<double> gather_points(int dim, std::span<const double> points, std::span<const NodeId> nodes) {
    std::vector<double> out(nodes.size() * static_cast<std::size_t>(dim));
    // A plain loop: std::copy_n of a run-time `dim` doubles is a memmove call per node.
    for (std::size_t i = 0; i < nodes.size(); ++i) {
        const double* x = points.data() + static_cast<std::size_t>(nodes[i]) * dim;
        for (int d = 0; d < dim; ++d) out[i * dim + d] = x[d];
    }
    return out;
}

BoundingBox bounding_box(const Mesh& mesh) {
    BoundingBox box;
    const std::size_t n = mesh.num_points(), dim = static_cast<std::size_t>(mesh.dim);
    if (n == 0) return box;
    for (std::size_t d = 0; d < dim; ++d) box.min[d] = box.max[d] = mesh.points[d];
    for (std::size_t i = 1; i < n; ++i)
        for (std::size_t d = 0; d < dim; ++d) {
            const double x = mesh.points[i * dim + d];
            box.min[d] = std::min(box.min[d], x);
            box.max[d] = std::max(box.max[d], x);
        }
    return box;
}

BoundingBox bounding_box(int dim, std::span<const double> points, std::span<const NodeId> nodes) {
    BoundingBox box;
    if (nodes.empty()) return box;
    for (int d = 0; d < dim; ++d) box.min[d] = box.max[d] = points[static_cast<std::size_t>(nodes[0]) * dim + d];
    for (NodeId n : nodes)
        for (int d = 0; d < dim; ++d) {
            const double x = points[static_cast<std::size_t>(n) * dim + d];
            box.min[d] = std::min(box.min[d], x);
            box.max[d] = std::max(box.max[d], x);
        }
    return box;
}

namespace {

/// Throws MeshError when element i of `list` is not as check_elements wants it.
void check_element(const ElementList& list, std::size_t i, std::int64_t num_points, int expected_dim,
                   const std::string& what, const std::string& marker, bool vertices) {
    const CellType t = list.types[i];
    const auto nodes = list.nodes_of(i);
    const bool count_ok = t == CellType::polygon      ? nodes.size() >= 3
                          : t == CellType::polyhedron ? nodes.size() >= 4
                                                      : static_cast<int>(nodes.size()) == nodes_per_cell(t);
    if (!count_ok)
        throw MeshError(what + " element " + std::to_string(i) + " (" + std::string(cell_type_name(t)) +
                            ") has " + std::to_string(nodes.size()) + " nodes",
                        marker, static_cast<std::int64_t>(i));
    const auto [f0, f1] = list.faces_of(i);
    if ((t == CellType::polyhedron) != (f1 > f0) || (t == CellType::polyhedron && f1 - f0 < 4))
        throw MeshError(what + " element " + std::to_string(i) + " (" + std::string(cell_type_name(t)) + ") has " +
                            std::to_string(f1 - f0) + " faces" +
                            (t == CellType::polyhedron ? " (a polyhedron has at least 4)" : ""),
                        marker, static_cast<std::int64_t>(i));
    for (std::int64_t f = f0; f < f1; ++f) {
        const auto ring = list.face_nodes_of(f);
        if (ring.size() < 3)
            throw MeshError(what + " element " + std::to_string(i) + " (polyhedron) has a face of " +
                                std::to_string(ring.size()) + " nodes",
                            marker, static_cast<std::int64_t>(i));
        for (NodeId n : ring)
            if (std::find(nodes.begin(), nodes.end(), n) == nodes.end())
                throw MeshError(what + " element " + std::to_string(i) + " (polyhedron): a face names node " +
                                    std::to_string(n) + ", not one of the cell's nodes",
                                marker, static_cast<std::int64_t>(i));
    }
    if (cell_dimension(t) != expected_dim && !((expected_dim == 1 || vertices) && t == CellType::vertex))
        throw MeshError(what + " element " + std::to_string(i) + " is a " + std::string(cell_type_name(t)) +
                            ", expected an element of dimension " + std::to_string(expected_dim),
                        marker, static_cast<std::int64_t>(i));
    for (NodeId n : nodes)
        if (n < 0 || n >= num_points)
            throw MeshError(what + " element " + std::to_string(i) + " names node " + std::to_string(n) +
                                ", but the mesh has " + std::to_string(num_points) + " nodes",
                            marker, static_cast<std::int64_t>(i));
}

void check_elements(const ElementList& list, std::int64_t num_points, int expected_dim,
                    const std::string& what, const std::string& marker, bool vertices = false) {
    if (list.offsets.size() != list.size() + 1 || list.offsets.back() != static_cast<std::int64_t>(list.nodes.size()))
        throw MeshError(what + ": element offsets do not match the node list", marker);
    if (!list.face_first.empty() &&
        (list.face_first.size() != list.size() + 1 || list.face_first.back() + 1 != static_cast<std::int64_t>(list.face_offsets.size()) ||
         list.face_offsets.back() != static_cast<std::int64_t>(list.face_nodes.size())))
        throw MeshError(what + ": polyhedron face offsets do not match the face lists", marker);
    // The elements on the threads, in blocks; the error of the first element
    // that has one, as a loop in order would throw it.
    constexpr std::int64_t block = 1 << 14;
    const auto n = static_cast<std::int64_t>(list.size());
    const std::int64_t blocks = (n + block - 1) / block;
    std::vector<std::exception_ptr> errors(static_cast<std::size_t>(blocks));
    parallel_for(
        blocks,
        [&](std::int64_t b) {
            try {
                for (std::int64_t i = b * block; i < std::min(n, (b + 1) * block); ++i)
                    check_element(list, static_cast<std::size_t>(i), num_points, expected_dim, what, marker, vertices);
            } catch (...) {
                errors[static_cast<std::size_t>(b)] = std::current_exception();
            }
        },
        2);
    for (const std::exception_ptr& e : errors)
        if (e) std::rethrow_exception(e);
}

void validate_as(const Mesh& mesh, bool point_cloud) {
    if (mesh.dim != 2 && mesh.dim != 3)
        throw MeshError("mesh dimension is " + std::to_string(mesh.dim) + ", expected 2 or 3");
    if (mesh.points.size() % static_cast<std::size_t>(mesh.dim) != 0)
        throw MeshError("point array length is not a multiple of the dimension");
    // Without cells nothing can be measured, deformed or written so that a reader takes it back.
    if (!point_cloud && mesh.cells.empty())
        throw MeshError("the mesh has no cells (no " + std::to_string(mesh.dim) +
                        "D elements); dgwarp needs a surface or volume mesh");
    if (point_cloud && !mesh.cells.empty()) throw MeshError("a point cloud has no cells");
    const auto n = static_cast<std::int64_t>(mesh.num_points());
    check_elements(mesh.cells, n, mesh.dim, "cell", "");
    for (const Marker& m : mesh.markers)
        check_elements(m.elements, n, mesh.dim - 1, "marker '" + m.name + "'", m.name, point_cloud);
    // A motion names markers: two of one name would move (or fix) both.
    for (std::size_t i = 0; i < mesh.markers.size(); ++i)
        for (std::size_t j = 0; j < i; ++j)
            if (mesh.markers[i].name == mesh.markers[j].name)
                throw MeshError("markers " + std::to_string(j + 1) + " and " + std::to_string(i + 1) +
                                    " are both named '" + mesh.markers[i].name +
                                    "'; marker names must be unique (a motion names markers)",
                                mesh.markers[i].name);
}
}  // namespace

void validate(const Mesh& mesh) { validate_as(mesh, false); }

void check_fixed_cell_types(const Mesh& mesh, std::string_view format) {
    const auto refuse = [&](const std::string& what, CellType t, const std::string& marker, std::size_t i) {
        throw MeshError(what + " " + std::to_string(i) + " is a " + std::string(cell_type_name(t)) + ", which " +
                            std::string(format) + " files cannot hold (write .vtu, .cgns or an OpenFOAM case)",
                        marker, static_cast<std::int64_t>(i));
    };
    for (std::size_t i = 0; i < mesh.cells.size(); ++i)
        if (has_any_node_count(mesh.cells.types[i])) refuse("cell", mesh.cells.types[i], "", i);
    for (const Marker& m : mesh.markers)
        for (std::size_t i = 0; i < m.elements.size(); ++i)
            if (has_any_node_count(m.elements.types[i]))
                refuse("marker '" + m.name + "' element", m.elements.types[i], m.name, i);
}

void validate_point_cloud(const Mesh& mesh) { validate_as(mesh, true); }

}  // namespace dgwarp
