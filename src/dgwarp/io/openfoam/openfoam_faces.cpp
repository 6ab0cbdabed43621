// OpenFOAM's faces from the cells of a mesh (openfoam_poly_mesh.hpp), for the writer.
#include <algorithm>
#include <limits>
#include <span>
#include <string>
#include <vector>

#include "dgwarp/core/error.hpp"
#include "dgwarp/io/openfoam/openfoam_poly_mesh.hpp"

namespace dgwarp::foam {

namespace {

/// A face of a cell, keyed by its sorted nodes, for finding the two cells of
/// each face: its 4 smallest node ids (a triangle's padded with -1) and its
/// size; a face of more than 4 nodes (a polyhedron's) also by all of them
/// (`full`, an index into the sorted lists kept beside).
struct KeyedFace {
    std::array<NodeId, 4> key;
    int size;
    std::int64_t full;  // -1 for 3 or 4 nodes
    std::int64_t cell;
    std::int64_t local;  // face index in outward_faces(type of cell), or a polyhedron's face id
};

std::array<NodeId, 4> face_key(std::span<const NodeId> nodes) {
    // A triangle's key starts with -1: triangles and quadrilaterals sort apart.
    std::array<NodeId, 4> k{-1, -1, -1, -1};
    if (nodes.size() > 4) {
        std::vector<NodeId> sorted(nodes.begin(), nodes.end());
        std::partial_sort(sorted.begin(), sorted.begin() + 4, sorted.end());
        std::copy_n(sorted.begin(), 4, k.begin());
        return k;
    }
    const std::size_t n = nodes.size();
    for (std::size_t i = 0; i < n; ++i) k[4 - n + i] = nodes[i];
    for (std::size_t i = 5 - n; i < 4; ++i)  // insertion sort of the last n
        for (std::size_t j = i; j > 4 - n && k[j] < k[j - 1]; --j) std::swap(k[j], k[j - 1]);
    return k;
}

/// The nodes of face `local` of cell c, turned out of the cell.
/// The nodes of face `local` of cell c, turned out of the cell, into `out`
/// (reused: no allocation per face once it has grown).
std::span<const NodeId> cell_face(const Mesh& mesh, std::int64_t c, std::int64_t local, std::vector<NodeId>& out) {
    const auto cell = static_cast<std::size_t>(c);
    if (mesh.cells.types[cell] == CellType::polyhedron) {
        const auto ring = mesh.cells.face_nodes_of(local);
        out.assign(ring.begin(), ring.end());
        return out;
    }
    const auto nodes = mesh.cells.nodes_of(cell);
    const FaceTable& t = outward_faces(mesh.cells.types[cell]);
    out.resize(static_cast<std::size_t>(t.size[local]));
    for (int i = 0; i < t.size[local]; ++i) out[static_cast<std::size_t>(i)] = nodes[static_cast<std::size_t>(t.node[local][i])];
    return out;
}

/// The faces of cell c: (local index, nodes out of the cell).
template <class F>
void for_each_cell_face(const Mesh& mesh, std::int64_t c, F&& f) {
    const auto cell = static_cast<std::size_t>(c);
    if (mesh.cells.types[cell] == CellType::polyhedron) {
        const auto [f0, f1] = mesh.cells.faces_of(cell);
        for (std::int64_t k = f0; k < f1; ++k) f(k, mesh.cells.face_nodes_of(k));
        return;
    }
    const FaceTable& t = outward_faces(mesh.cells.types[cell]);
    const auto nodes = mesh.cells.nodes_of(cell);
    for (int k = 0; k < t.count; ++k) {
        NodeId face[4];
        for (int i = 0; i < t.size[k]; ++i) face[i] = nodes[static_cast<std::size_t>(t.node[k][i])];
        f(std::int64_t{k}, std::span<const NodeId>(face, static_cast<std::size_t>(t.size[k])));
    }
}

std::string nodes_text(std::span<const NodeId> nodes) {
    std::string s;
    for (NodeId n : nodes) s += (s.empty() ? "" : " ") + std::to_string(n);
    return s;
}

}  // namespace

PolyMesh faces_from_cells(const Mesh& mesh) {
    if (mesh.dim != 3)
        throw MeshError("OpenFOAM meshes are 3D: a " + std::to_string(mesh.dim) +
                        "D mesh cannot be written as a polyMesh (extrude it to one cell thick first, e.g. with "
                        "OpenFOAM's extrudeMesh)");
    validate(mesh);
    const auto ncells = static_cast<std::int64_t>(mesh.cells.size());
    check_label_size(ncells, 0);
    std::vector<KeyedFace> all;
    std::vector<std::vector<NodeId>> full;  // sorted nodes of the faces of more than 4
    all.reserve(mesh.cells.size() * 6);
    for (std::int64_t c = 0; c < ncells; ++c)
        for_each_cell_face(mesh, c, [&](std::int64_t local, std::span<const NodeId> face) {
            std::int64_t f = -1;
            if (face.size() > 4) {
                f = static_cast<std::int64_t>(full.size());
                full.emplace_back(face.begin(), face.end());
                std::sort(full.back().begin(), full.back().end());
            }
            all.push_back({face_key(face), static_cast<int>(face.size()), f, c, local});
        });
    const auto same_face = [&](const KeyedFace& a, const KeyedFace& b) {
        return a.key == b.key && a.size == b.size &&
               (a.full < 0 || full[static_cast<std::size_t>(a.full)] == full[static_cast<std::size_t>(b.full)]);
    };
    const auto face_before = [&](const KeyedFace& a, const KeyedFace& b) {
        if (a.key != b.key) return a.key < b.key;
        if (a.size != b.size) return a.size < b.size;
        if (a.full >= 0 && full[static_cast<std::size_t>(a.full)] != full[static_cast<std::size_t>(b.full)])
            return full[static_cast<std::size_t>(a.full)] < full[static_cast<std::size_t>(b.full)];
        return false;
    };
    // Whether face f holds exactly the nodes of `element`.
    const auto same_face_probe = [&](const KeyedFace& f, std::span<const NodeId> element) {
        if (f.size != static_cast<int>(element.size()) || f.key != face_key(element)) return false;
        if (f.full < 0) return true;
        std::vector<NodeId> sorted(element.begin(), element.end());
        std::sort(sorted.begin(), sorted.end());
        return full[static_cast<std::size_t>(f.full)] == sorted;
    };
    std::sort(all.begin(), all.end(), [&](const KeyedFace& a, const KeyedFace& b) {
        if (face_before(a, b)) return true;
        if (face_before(b, a)) return false;
        return a.cell != b.cell ? a.cell < b.cell : a.local < b.local;
    });

    struct Internal {
        std::int64_t owner, neighbour;
        std::int64_t local;
    };
    std::vector<Internal> internal;
    std::vector<KeyedFace> boundary;  // sorted by key
    std::vector<NodeId> a, b, turned;  // a face's nodes, reused
    for (std::size_t i = 0; i < all.size();) {
        std::size_t j = i + 1;
        while (j < all.size() && same_face(all[j], all[i])) ++j;
        if (j - i > 2)
            throw MeshError("cells " + std::to_string(all[i].cell) + ", " + std::to_string(all[i + 1].cell) + " and " +
                                std::to_string(all[i + 2].cell) + " share a face (nodes " +
                                nodes_text(cell_face(mesh, all[i].cell, all[i].local, a)) +
                                "): OpenFOAM faces have at most two cells",
                            "", all[i].cell);
        if (j - i == 2) {
            cell_face(mesh, all[i].cell, all[i].local, a);
            cell_face(mesh, all[i + 1].cell, all[i + 1].local, b);
            const auto n = static_cast<int>(a.size());
            std::reverse(b.begin(), b.end());
            if (!same_cycle(a.data(), b.data(), n))
                throw MeshError("cells " + std::to_string(all[i].cell) + " and " + std::to_string(all[i + 1].cell) +
                                    " share the face " + nodes_text(a) +
                                    " with the same orientation: one of them is inverted (its nodes in mirrored "
                                    "order), and OpenFOAM's faces point out of their owner",
                                "", all[i + 1].cell);
            internal.push_back({all[i].cell, all[i + 1].cell, all[i].local});
        } else {
            boundary.push_back(all[i]);
        }
        i = j;
    }
    std::sort(internal.begin(), internal.end(), [](const Internal& a, const Internal& b) {
        return a.owner != b.owner ? a.owner < b.owner : a.neighbour != b.neighbour ? a.neighbour < b.neighbour
                                                                                   : a.local < b.local;
    });

    PolyMesh pm;
    pm.points = mesh.points;
    pm.face_nodes.reserve(internal.size() * 4 + boundary.size() * 4);
    pm.face_offsets.reserve(internal.size() + boundary.size() + 1);
    const auto add_face = [&pm](std::span<const NodeId> nodes, std::int64_t owner) {
        pm.face_nodes.insert(pm.face_nodes.end(), nodes.begin(), nodes.end());
        pm.face_offsets.push_back(static_cast<std::int64_t>(pm.face_nodes.size()));
        pm.owner.push_back(static_cast<std::int32_t>(owner));  // in range: check_label_size above
    };
    for (const Internal& f : internal) {
        add_face(cell_face(mesh, f.owner, f.local, a), f.owner);
        pm.neighbour.push_back(static_cast<std::int32_t>(f.neighbour));
    }

    // Patches: the markers' elements, each found among the boundary faces.
    std::vector<std::int64_t> taken(boundary.size(), -1);  // marker holding each boundary face
    for (std::size_t m = 0; m < mesh.markers.size(); ++m) {
        const Marker& marker = mesh.markers[m];
        Patch patch{marker.name, {}, static_cast<std::int64_t>(pm.num_faces()),
                    static_cast<std::int64_t>(marker.elements.size()), 0, false, {}};
        for (std::size_t e = 0; e < marker.elements.size(); ++e) {
            const auto element = marker.elements.nodes_of(e);
            KeyedFace probe{face_key(element), static_cast<int>(element.size()), -1, 0, 0};
            if (element.size() > 4) {
                probe.full = static_cast<std::int64_t>(full.size());
                full.emplace_back(element.begin(), element.end());
                std::sort(full.back().begin(), full.back().end());
            }
            const auto it = std::lower_bound(boundary.begin(), boundary.end(), probe, face_before);
            const bool found = it != boundary.end() && !face_before(probe, *it) && same_face_probe(*it, element);
            if (probe.full >= 0) full.pop_back();
            if (!found)
                throw MeshError("marker '" + marker.name + "' element " + std::to_string(e) + " (nodes " +
                                    nodes_text(element) +
                                    ") is not a boundary face of the cells (an inner face, or no face of "
                                    "any cell): OpenFOAM patches hold boundary faces only",
                                marker.name, static_cast<std::int64_t>(e));
            const auto b = static_cast<std::size_t>(it - boundary.begin());
            if (taken[b] >= 0)
                throw MeshError("marker '" + marker.name + "' element " + std::to_string(e) + " (nodes " +
                                    nodes_text(element) + ") is also in marker '" +
                                    mesh.markers[static_cast<std::size_t>(taken[b])].name +
                                    "': an OpenFOAM face is in one patch",
                                marker.name, static_cast<std::int64_t>(e));
            taken[b] = static_cast<std::int64_t>(m);
            // The cell's outward face, from the element's first node.
            const std::span<const NodeId> face = cell_face(mesh, it->cell, it->local, a);
            const std::size_t n = face.size();
            const auto at = static_cast<std::size_t>(std::find(face.begin(), face.end(), element[0]) - face.begin());
            turned.resize(n);
            for (std::size_t i = 0; i < n; ++i) turned[i] = face[(at + i) % n];
            add_face(turned, it->cell);
        }
        pm.patches.push_back(std::move(patch));
    }
    std::vector<const KeyedFace*> rest;
    for (std::size_t b = 0; b < boundary.size(); ++b)
        if (taken[b] < 0) rest.push_back(&boundary[b]);
    if (!rest.empty()) {
        std::sort(rest.begin(), rest.end(), [](const KeyedFace* a, const KeyedFace* b) {
            return a->cell != b->cell ? a->cell < b->cell : a->local < b->local;
        });
        Patch patch{"defaultFaces", {}, static_cast<std::int64_t>(pm.num_faces()),
                    static_cast<std::int64_t>(rest.size()), 0, false, {}};
        for (const KeyedFace* f : rest) add_face(cell_face(mesh, f->cell, f->local, a), f->cell);
        pm.patches.push_back(std::move(patch));
    }
    check_label_size(ncells, static_cast<std::int64_t>(pm.face_nodes.size()));
    return pm;
}

void check_label_size(std::int64_t cells, std::int64_t face_node_entries) {
    constexpr std::int64_t most = std::numeric_limits<std::int32_t>::max();
    const auto refuse = [](std::int64_t n, const char* what) {
        throw MeshError("the mesh has " + std::to_string(n) + " " + what +
                        ", more than the 32-bit labels of an OpenFOAM polyMesh hold (2147483647)");
    };
    if (cells > most) refuse(cells, "cells");
    if (face_node_entries > most) refuse(face_node_entries, "face-node entries in its faces");
}

}  // namespace dgwarp::foam
