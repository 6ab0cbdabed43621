// OpenFOAM's faces from the cells of a mesh (openfoam_poly_mesh.hpp), for the writer.
#include <algorithm>
#include <limits>
#include <span>
#include <string>

#include "dgwarp/core/error.hpp"
#include "dgwarp/io/openfoam_poly_mesh.hpp"

namespace dgwarp::foam {

namespace {

/// A face of a cell, keyed by its sorted nodes, for finding the two cells of each face.
struct KeyedFace {
    std::array<NodeId, 4> key;  // sorted; a triangle's fourth is -1
    std::int64_t cell;
    int local;  // face index in outward_faces(type of cell)
};

std::array<NodeId, 4> face_key(std::span<const NodeId> nodes) {
    // A triangle's key starts with -1: triangles and quadrilaterals sort apart.
    std::array<NodeId, 4> k{-1, -1, -1, -1};
    const std::size_t n = std::min<std::size_t>(nodes.size(), 4);
    for (std::size_t i = 0; i < n; ++i) k[4 - n + i] = nodes[i];
    for (std::size_t i = 5 - n; i < 4; ++i)  // insertion sort of the last n
        for (std::size_t j = i; j > 4 - n && k[j] < k[j - 1]; --j) std::swap(k[j], k[j - 1]);
    return k;
}

/// The nodes of face `local` of cell c, turned out of the cell.
int cell_face(const Mesh& mesh, std::int64_t c, int local, NodeId* out) {
    const auto nodes = mesh.cells.nodes_of(static_cast<std::size_t>(c));
    const FaceTable& t = outward_faces(mesh.cells.types[static_cast<std::size_t>(c)]);
    for (int i = 0; i < t.size[local]; ++i) out[i] = nodes[static_cast<std::size_t>(t.node[local][i])];
    return t.size[local];
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
    all.reserve(mesh.cells.size() * 6);
    for (std::int64_t c = 0; c < ncells; ++c) {
        const FaceTable& t = outward_faces(mesh.cells.types[static_cast<std::size_t>(c)]);
        for (int k = 0; k < t.count; ++k) {
            NodeId face[4];
            const int n = cell_face(mesh, c, k, face);
            all.push_back({face_key({face, static_cast<std::size_t>(n)}), c, k});
        }
    }
    std::sort(all.begin(), all.end(), [](const KeyedFace& a, const KeyedFace& b) {
        return a.key != b.key ? a.key < b.key : a.cell != b.cell ? a.cell < b.cell : a.local < b.local;
    });

    struct Internal {
        std::int64_t owner, neighbour;
        int local;
    };
    std::vector<Internal> internal;
    std::vector<KeyedFace> boundary;  // sorted by key
    for (std::size_t i = 0; i < all.size();) {
        std::size_t j = i + 1;
        while (j < all.size() && all[j].key == all[i].key) ++j;
        if (j - i > 2)
            throw MeshError("cells " + std::to_string(all[i].cell) + ", " + std::to_string(all[i + 1].cell) + " and " +
                                std::to_string(all[i + 2].cell) + " share a face (nodes " +
                                nodes_text({all[i].key.data() + (all[i].key[0] < 0), 4u - (all[i].key[0] < 0)}) +
                                "): OpenFOAM faces have at most two cells",
                            "", all[i].cell);
        if (j - i == 2) {
            NodeId a[4], b[4];
            const int n = cell_face(mesh, all[i].cell, all[i].local, a);
            cell_face(mesh, all[i + 1].cell, all[i + 1].local, b);
            std::reverse(b, b + n);
            if (!same_cycle(a, b, n))
                throw MeshError("cells " + std::to_string(all[i].cell) + " and " + std::to_string(all[i + 1].cell) +
                                    " share the face " + nodes_text({a, static_cast<std::size_t>(n)}) +
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
        NodeId face[4];
        const int n = cell_face(mesh, f.owner, f.local, face);
        add_face({face, static_cast<std::size_t>(n)}, f.owner);
        pm.neighbour.push_back(static_cast<std::int32_t>(f.neighbour));
    }

    // Patches: the markers' elements, each found among the boundary faces.
    std::vector<std::int64_t> taken(boundary.size(), -1);  // marker holding each boundary face
    for (std::size_t m = 0; m < mesh.markers.size(); ++m) {
        const Marker& marker = mesh.markers[m];
        Patch patch{marker.name, {}, static_cast<std::int64_t>(pm.num_faces()),
                    static_cast<std::int64_t>(marker.elements.size()), 0};
        for (std::size_t e = 0; e < marker.elements.size(); ++e) {
            const auto element = marker.elements.nodes_of(e);
            const KeyedFace probe{face_key(element), 0, 0};
            const auto it = std::lower_bound(boundary.begin(), boundary.end(), probe,
                                             [](const KeyedFace& a, const KeyedFace& b) { return a.key < b.key; });
            if (it == boundary.end() || it->key != probe.key)
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
            NodeId face[4], turned[4];
            const int n = cell_face(mesh, it->cell, it->local, face);
            const int at = static_cast<int>(std::find(face, face + n, element[0]) - face);
            for (int i = 0; i < n; ++i) turned[i] = face[(at + i) % n];
            add_face({turned, static_cast<std::size_t>(n)}, it->cell);
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
                    static_cast<std::int64_t>(rest.size()), 0};
        for (const KeyedFace* f : rest) {
            NodeId face[4];
            const int n = cell_face(mesh, f->cell, f->local, face);
            add_face({face, static_cast<std::size_t>(n)}, f->cell);
        }
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
