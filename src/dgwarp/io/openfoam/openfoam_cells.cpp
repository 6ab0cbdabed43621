// Cells from OpenFOAM's faces (openfoam_poly_mesh.hpp).
#include <algorithm>
#include <exception>
#include <span>
#include <string>
#include <vector>

#include "dgwarp/core/error.hpp"
#include "dgwarp/core/parallel_for.hpp"
#include "dgwarp/io/record_lines.hpp"
#include "dgwarp/io/openfoam/openfoam_poly_mesh.hpp"

namespace dgwarp::foam {

bool same_cycle(const NodeId* a, const NodeId* b, int n) {
    for (int r = 0; r < n; ++r) {
        bool equal = true;
        for (int i = 0; i < n && equal; ++i) equal = a[i] == b[(i + r) % n];
        if (equal) return true;
    }
    return false;
}

const FaceTable& outward_faces(CellType type) {
    // VTK node order, positive orientation (cell_orientation +1): a
    // tetrahedron's and a pyramid's base and a hexahedron's bottom face turn
    // counter-clockwise seen from the rest of the cell, a prism's first
    // triangle clockwise (docs/QUALITY.md).
    static const FaceTable tet{4, {3, 3, 3, 3}, {{{0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {2, 0, 3}}}};
    static const FaceTable pyramid{5, {4, 3, 3, 3, 3}, {{{0, 3, 2, 1}, {0, 1, 4}, {1, 2, 4}, {2, 3, 4}, {3, 0, 4}}}};
    static const FaceTable prism{5, {3, 3, 4, 4, 4}, {{{0, 1, 2}, {3, 5, 4}, {0, 3, 4, 1}, {1, 4, 5, 2}, {2, 5, 3, 0}}}};
    static const FaceTable hex{
        6, {4, 4, 4, 4, 4, 4}, {{{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4}, {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7}}}};
    static const FaceTable none{};
    switch (type) {
        case CellType::tetrahedron: return tet;
        case CellType::pyramid: return pyramid;
        case CellType::prism: return prism;
        case CellType::hexahedron: return hex;
        default: return none;
    }
}

void push_canonical_polyhedron(std::span<const NodeId> rings, std::span<const int> sizes, ElementList& out) {
    // Each face as a cycle from its smallest node, the faces in the order of those cycles.
    std::vector<std::vector<NodeId>> faces;
    std::size_t at = 0;
    for (int size : sizes) {
        const auto ring = rings.subspan(at, static_cast<std::size_t>(size));
        const std::size_t first = static_cast<std::size_t>(std::min_element(ring.begin(), ring.end()) - ring.begin());
        std::vector<NodeId> cycle(ring.size());
        for (std::size_t k = 0; k < ring.size(); ++k) cycle[k] = ring[(first + k) % ring.size()];
        faces.push_back(std::move(cycle));
        at += static_cast<std::size_t>(size);
    }
    std::sort(faces.begin(), faces.end());
    std::vector<NodeId> sorted;
    std::vector<int> sorted_sizes;
    for (const auto& f : faces) {
        sorted.insert(sorted.end(), f.begin(), f.end());
        sorted_sizes.push_back(static_cast<int>(f.size()));
    }
    out.push_polyhedron(sorted, sorted_sizes);
}

void push_cell_from_faces(std::span<const NodeId> rings, std::span<const int> sizes, ElementList& out) {
    if (sizes.size() <= 6 && std::all_of(sizes.begin(), sizes.end(), [](int n) { return n <= 4; })) {
        CellFaces cf;
        std::size_t at = 0;
        for (int size : sizes) {
            cf.size[static_cast<std::size_t>(cf.count)] = size;
            for (int i = 0; i < size; ++i) cf.node[static_cast<std::size_t>(cf.count)][static_cast<std::size_t>(i)] = rings[at++];
            ++cf.count;
        }
        const OrderedCell oc = order_cell(cf);
        if (oc.shape == CellShape::ok) {
            out.push_back(oc.type, {oc.node.data(), static_cast<std::size_t>(nodes_per_cell(oc.type))});
            return;
        }
    }
    push_canonical_polyhedron(rings, sizes, out);
}

namespace {

/// The face of `f` holding the directed edge a -> b: its index and the
/// position of a in it, or index -1.
struct FaceAt {
    int face = -1;
    int at = 0;
};

FaceAt face_with_edge(const CellFaces& f, NodeId a, NodeId b) {
    for (int k = 0; k < f.count; ++k)
        for (int i = 0; i < f.size[k]; ++i)
            if (f.node[k][i] == a && f.node[k][(i + 1) % f.size[k]] == b) return {k, i};
    return {};
}

/// Node j after `at` along face k.
NodeId along(const CellFaces& f, FaceAt p, int j) { return f.node[p.face][(p.at + j) % f.size[p.face]]; }

/// The nodes joined to v by an edge of a face, without repeats.
int neighbours_of(const CellFaces& f, NodeId v, std::array<NodeId, 8>& out) {
    int n = 0;
    for (int k = 0; k < f.count; ++k)
        for (int i = 0; i < f.size[k]; ++i)
            if (f.node[k][i] == v) {
                const NodeId w = f.node[k][(i + 1) % f.size[k]];
                if (std::find(out.begin(), out.begin() + n, w) == out.begin() + n) {
                    if (n == 8) return n;
                    out[n++] = w;
                }
            }
    return n;
}

/// The one neighbour of v that is not among `base` (-1 when there is none or several).
NodeId partner(const CellFaces& f, NodeId v, std::span<const NodeId> base) {
    std::array<NodeId, 8> nb{};
    const int n = neighbours_of(f, v, nb);
    NodeId found = -1;
    for (int i = 0; i < n; ++i)
        if (std::find(base.begin(), base.end(), nb[i]) == base.end()) {
            if (found >= 0) return -1;
            found = nb[i];
        }
    return found;
}

/// Every face of the ordered cell is one of `f` (as a cycle), and the nodes are distinct.
bool faces_match(const CellFaces& f, CellType type, const std::array<NodeId, 8>& node) {
    const int n = nodes_per_cell(type);
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < i; ++j)
            if (node[i] == node[j] || node[i] < 0) return false;
    const FaceTable& table = outward_faces(type);
    if (table.count != f.count) return false;
    for (int k = 0; k < table.count; ++k) {
        NodeId face[4];
        for (int i = 0; i < table.size[k]; ++i) face[i] = node[table.node[k][i]];
        bool found = false;
        for (int j = 0; j < f.count && !found; ++j)
            found = f.size[j] == table.size[k] && same_cycle(face, f.node[j].data(), f.size[j]);
        if (!found) return false;
    }
    return true;
}

NodeId smallest_node(const CellFaces& f) {
    NodeId m = f.node[0][0];
    for (int k = 0; k < f.count; ++k)
        for (int i = 0; i < f.size[k]; ++i) m = std::min(m, f.node[k][i]);
    return m;
}

/// Tetrahedron or hexahedron: v0 the smallest node, v1 its smallest neighbour,
/// the base the face turning v0 -> v1 seen from inside (the outward face
/// holding v1 -> v0, reversed).
bool order_from_smallest_edge(const CellFaces& f, int base_size, std::array<NodeId, 8>& node) {
    const NodeId v0 = smallest_node(f);
    std::array<NodeId, 8> nb{};
    const int n = neighbours_of(f, v0, nb);
    if (n == 0) return false;
    const NodeId v1 = *std::min_element(nb.begin(), nb.begin() + n);
    const FaceAt p = face_with_edge(f, v1, v0);
    if (p.face < 0 || f.size[p.face] != base_size) return false;
    node[0] = v0;
    for (int j = 1; j < base_size; ++j) node[j] = along(f, p, base_size - j + 1);  // v1, then backwards
    return true;
}

/// The partner of each of the first `base_size` nodes goes `base_size` places later.
bool add_partners(const CellFaces& f, int base_size, std::array<NodeId, 8>& node) {
    const std::span<const NodeId> base(node.data(), static_cast<std::size_t>(base_size));
    for (int j = 0; j < base_size; ++j)
        if ((node[base_size + j] = partner(f, node[j], base)) < 0) return false;
    return true;
}

}  // namespace

OrderedCell order_cell(const CellFaces& f) {
    OrderedCell c;
    int tris = 0, quads = 0;
    for (int k = 0; k < f.count; ++k) {
        if (f.size[k] == 3) ++tris;
        else if (f.size[k] == 4) ++quads;
        else return c;  // polyhedron
    }
    if (f.count == 4 && tris == 4) c.type = CellType::tetrahedron;
    else if (f.count == 5 && tris == 4) c.type = CellType::pyramid;
    else if (f.count == 5 && tris == 2) c.type = CellType::prism;
    else if (f.count == 6 && quads == 6) c.type = CellType::hexahedron;
    else return c;
    c.shape = CellShape::not_closed;
    bool ok = false;
    switch (c.type) {
        case CellType::tetrahedron:
            ok = order_from_smallest_edge(f, 3, c.node);
            if (ok) {
                // The apex: the node not in the base.
                c.node[3] = -1;
                for (int k = 0; k < f.count; ++k)
                    for (int i = 0; i < f.size[k]; ++i)
                        if (std::find(c.node.begin(), c.node.begin() + 3, f.node[k][i]) == c.node.begin() + 3)
                            c.node[3] = f.node[k][i];
            }
            break;
        case CellType::hexahedron:
            ok = order_from_smallest_edge(f, 4, c.node) && add_partners(f, 4, c.node);
            break;
        case CellType::prism: {
            // The first triangle holds the smallest node and keeps its outward turn.
            const NodeId v0 = smallest_node(f);
            for (int k = 0; k < f.count && !ok; ++k)
                for (int i = 0; i < f.size[k] && !ok; ++i)
                    if (f.size[k] == 3 && f.node[k][i] == v0) {
                        for (int j = 0; j < 3; ++j) c.node[j] = f.node[k][(i + j) % 3];
                        ok = true;
                    }
            ok = ok && add_partners(f, 3, c.node);
            break;
        }
        case CellType::pyramid: {
            int q = 0;
            while (f.size[q] != 4) ++q;
            int at = 0;
            for (int i = 1; i < 4; ++i)
                if (f.node[q][i] < f.node[q][at]) at = i;
            for (int j = 0; j < 4; ++j) c.node[j] = f.node[q][(at + 4 - j) % 4];  // the base turned inward
            c.node[4] = -1;
            for (int k = 0; k < f.count; ++k)
                for (int i = 0; i < f.size[k]; ++i)
                    if (std::find(c.node.begin(), c.node.begin() + 4, f.node[k][i]) == c.node.begin() + 4)
                        c.node[4] = f.node[k][i];
            ok = true;
            break;
        }
        default: break;
    }
    if (ok && faces_match(f, c.type, c.node)) c.shape = CellShape::ok;
    return c;
}

ElementList cells_from_faces(const PolyMesh& mesh, std::int64_t num_cells, const FaceLines& where) {
    const auto nfaces = static_cast<std::int64_t>(mesh.num_faces());
    const auto ninternal = static_cast<std::int64_t>(mesh.neighbour.size());
    // Each cell's faces (compressed rows): f for a face it owns, ~f for one it neighbours.
    std::vector<std::int64_t> start(static_cast<std::size_t>(num_cells) + 1, 0);
    for (std::int64_t f = 0; f < nfaces; ++f) ++start[static_cast<std::size_t>(mesh.owner[f]) + 1];
    for (std::int64_t f = 0; f < ninternal; ++f) ++start[static_cast<std::size_t>(mesh.neighbour[f]) + 1];
    for (std::size_t c = 0; c < static_cast<std::size_t>(num_cells); ++c) start[c + 1] += start[c];
    std::vector<std::int64_t> faces(static_cast<std::size_t>(start.back()));
    {
        std::vector<std::int64_t> fill(start.begin(), start.end() - 1);
        for (std::int64_t f = 0; f < nfaces; ++f) faces[fill[mesh.owner[f]]++] = f;
        for (std::int64_t f = 0; f < ninternal; ++f) faces[fill[mesh.neighbour[f]]++] = ~f;
    }
    const auto face_of = [](std::int64_t signed_face) { return signed_face < 0 ? ~signed_face : signed_face; };
    const auto line_of = [&](std::int64_t c) -> std::size_t {
        std::int64_t first = nfaces;
        for (std::int64_t k = start[c]; k < start[c + 1]; ++k) first = std::min(first, face_of(faces[k]));
        return first < nfaces && !where.line.empty() ? where.line[static_cast<std::size_t>(first)] : 0;
    };
    const auto face_list = [&](std::int64_t c) {
        std::string s;
        std::vector<std::int64_t> ids;
        for (std::int64_t k = start[c]; k < start[c + 1]; ++k) ids.push_back(face_of(faces[k]));
        std::sort(ids.begin(), ids.end());
        for (std::size_t i = 0; i < ids.size() && i < 8; ++i) s += (i ? ", " : "") + std::to_string(ids[i]);
        return s + (ids.size() > 8 ? ", ..." : "");
    };

    // The cells in chunks on the threads, each into a list of its own, a wave
    // of chunks at a time; each wave's lists are then joined to the cells in
    // order (so that only a wave's lists exist beside the cells). A chunk
    // stops at its first bad cell: the error of the first chunk that has one
    // is the first in cell order, the one a serial loop gives.
    constexpr std::int64_t chunk = 1 << 14;
    const std::int64_t chunks = (num_cells + chunk - 1) / chunk;
    const std::int64_t wave = 4 * std::max(1, num_threads());
    ElementList all;
    all.types.reserve(static_cast<std::size_t>(num_cells));
    all.offsets.reserve(static_cast<std::size_t>(num_cells) + 1);
    all.nodes.reserve(static_cast<std::size_t>(num_cells) * 4);
    std::vector<ElementList> parts;
    std::vector<std::exception_ptr> errors;
    for (std::int64_t first_chunk = 0; first_chunk < chunks; first_chunk += wave) {
        const std::int64_t in_wave = std::min(wave, chunks - first_chunk);
        parts.assign(static_cast<std::size_t>(in_wave), ElementList{});
        errors.assign(static_cast<std::size_t>(in_wave), nullptr);
        parallel_for(
            in_wave,
            [&](std::int64_t w) {
                try {
                    const std::int64_t p = first_chunk + w;
                    const std::int64_t first = p * chunk, last = std::min(num_cells, first + chunk);
                    ElementList& cells = parts[static_cast<std::size_t>(w)];
                    cells.reserve(static_cast<std::size_t>(last - first), 8);
                    std::vector<NodeId> rings;
                    std::vector<int> sizes;
                    std::vector<std::pair<NodeId, NodeId>> edges, reversed;
                    for (std::int64_t c = first; c < last; ++c) {
                        const std::int64_t count = start[c + 1] - start[c];
                        if (count == 0)
                            throw ParseError(where.owner_file, 0,
                                             "every cell from 0 to " + std::to_string(num_cells - 1) +
                                                 " (the largest in owner and neighbour) to own or neighbour faces",
                                             "cell " + std::to_string(c) + " has none");
                        // The cell's faces pointing out of it: a face points out of its owner, the neighbour sees it reversed.
                        rings.clear();
                        sizes.clear();
                        for (std::int64_t k = start[c]; k < start[c + 1]; ++k) {
                            const std::int64_t f = face_of(faces[k]);
                            const auto size = static_cast<int>(mesh.face_offsets[f + 1] - mesh.face_offsets[f]);
                            for (int i = 0; i < size; ++i) {
                                const int j = faces[k] >= 0 ? i : (size - i) % size;
                                rings.push_back(mesh.face_nodes[mesh.face_offsets[f] + j]);
                            }
                            sizes.push_back(size);
                        }
                        bool simple = count <= 6 && std::all_of(sizes.begin(), sizes.end(), [](int n) { return n <= 4; });
                        CellFaces cf;
                        if (simple) {
                            std::size_t at = 0;
                            for (int size : sizes) {
                                cf.size[cf.count] = size;
                                for (int i = 0; i < size; ++i) cf.node[cf.count][i] = rings[at++];
                                ++cf.count;
                            }
                        }
                        const OrderedCell oc = simple ? order_cell(cf) : OrderedCell{};
                        if (oc.shape == CellShape::not_closed)
                            throw ParseError(where.faces_file, line_of(c),
                                             "the faces of cell " + std::to_string(c) + " (faces " + face_list(c) +
                                                 ", oriented by owner and neighbour) to close a " +
                                                 std::string(cell_type_name(oc.type)),
                                             "faces that do not");
                        if (oc.shape == CellShape::ok) {
                            cells.push_back(oc.type, {oc.node.data(), static_cast<std::size_t>(nodes_per_cell(oc.type))});
                            continue;
                        }
                        // A polyhedron: closed when each edge of its faces is met once each way.
                        edges.clear();
                        reversed.clear();
                        std::size_t at = 0;
                        for (int size : sizes) {
                            for (int i = 0; i < size; ++i) {
                                const NodeId a = rings[at + static_cast<std::size_t>(i)],
                                             b = rings[at + static_cast<std::size_t>((i + 1) % size)];
                                edges.emplace_back(a, b);
                                reversed.emplace_back(b, a);
                            }
                            at += static_cast<std::size_t>(size);
                        }
                        std::sort(edges.begin(), edges.end());
                        std::sort(reversed.begin(), reversed.end());
                        if (count < 4 || edges != reversed || std::adjacent_find(edges.begin(), edges.end()) != edges.end())
                            throw ParseError(where.faces_file, line_of(c),
                                             "the faces of cell " + std::to_string(c) + " (faces " + face_list(c) +
                                                 ", oriented by owner and neighbour) to close a polyhedron (each edge "
                                                 "once each way)",
                                             "faces that do not");
                        push_canonical_polyhedron(rings, sizes, cells);
                    }
                } catch (...) {
                    errors[static_cast<std::size_t>(w)] = std::current_exception();
                }
            },
            1);
        for (const std::exception_ptr& e : errors)
            if (e) std::rethrow_exception(e);
        append_element_parts(all, parts);
    }
    return all;
}

}  // namespace dgwarp::foam
