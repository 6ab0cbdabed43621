// prepare_laplacian: the cells split into simplices, the unknowns numbered.
#include <algorithm>
#include <array>
#include <initializer_list>
#include <limits>
#include <map>
#include <string>
#include <vector>

#include "dgwarp/core/error.hpp"
#include "dgwarp/methods/laplacian.hpp"
#include "dgwarp/methods/method_inputs.hpp"

namespace dgwarp {

namespace {

using Face = std::array<int, 4>;  // local corner indices; [3] = -1 for a triangle

// Faces of the 3D cells other than the tetrahedron (VTK corner order).
std::span<const Face> faces_of(CellType t) {
    static constexpr Face hexahedron[] = {{0, 1, 2, 3}, {4, 5, 6, 7}, {0, 1, 5, 4},
                                          {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7}};
    static constexpr Face prism[] = {{0, 1, 2, -1}, {3, 4, 5, -1}, {0, 1, 4, 3}, {1, 2, 5, 4}, {2, 0, 3, 5}};
    static constexpr Face pyramid[] = {{0, 1, 2, 3}, {0, 1, 4, -1}, {1, 2, 4, -1}, {2, 3, 4, -1}, {3, 0, 4, -1}};
    switch (t) {
        case CellType::hexahedron: return hexahedron;
        case CellType::prism: return prism;
        case CellType::pyramid: return pyramid;
        default: return {};
    }
}

// Each corner's dim neighbours along the cell's edges (VTK corner order), per cell type.
std::span<const std::array<int, 4>> corner_neighbours(CellType t) {
    static constexpr std::array<int, 4> quadrilateral[] = {{0, 1, 3, -1}, {1, 2, 0, -1}, {2, 3, 1, -1}, {3, 0, 2, -1}};
    static constexpr std::array<int, 4> hexahedron[] = {{0, 1, 3, 4}, {1, 2, 0, 5}, {2, 3, 1, 6}, {3, 0, 2, 7},
                                                        {4, 7, 5, 0}, {5, 4, 6, 1}, {6, 5, 7, 2}, {7, 6, 4, 3}};
    static constexpr std::array<int, 4> prism[] = {{0, 1, 2, 3}, {1, 2, 0, 4}, {2, 0, 1, 5},
                                                   {3, 5, 4, 0}, {4, 3, 5, 1}, {5, 4, 3, 2}};
    static constexpr std::array<int, 4> pyramid[] = {{0, 1, 3, 4}, {1, 2, 0, 4}, {2, 3, 1, 4}, {3, 0, 2, 4}};
    switch (t) {
        case CellType::quadrilateral: return quadrilateral;
        case CellType::hexahedron: return hexahedron;
        case CellType::prism: return prism;
        case CellType::pyramid: return pyramid;
        default: return {};
    }
}

bool is_simplex(int dim, CellType t) {
    return (dim == 2 && t == CellType::triangle) || (dim == 3 && t == CellType::tetrahedron);
}

// A quadrilateral face of a 3D cell: its sorted corners (the key two cells
// share), the cell and the face's corners in the cell's order.
struct QuadFace {
    std::array<NodeId, 4> key;
    std::int32_t cell;
    std::array<NodeId, 4> corners;
};

// Throws MeshError when a connected part of the split mesh has unknowns but
// no given node (a boundary node): its matrix would be singular.
void check_every_part_held(const LaplacianPlan& plan) {
    const std::size_t total = plan.unknown.size();
    std::vector<std::int32_t> parent(total);
    for (std::size_t n = 0; n < total; ++n) parent[n] = static_cast<std::int32_t>(n);
    const auto root = [&](std::int32_t n) {
        while (parent[n] != n) n = parent[n] = parent[parent[n]];
        return n;
    };
    const std::size_t corners = static_cast<std::size_t>(plan.dim) + 1;
    for (std::size_t s = 0; s < plan.simplices.size(); s += corners)
        for (std::size_t k = 1; k < corners; ++k) {
            const std::int32_t a = root(plan.simplices[s]), b = root(plan.simplices[s + k]);
            if (a != b) parent[std::max(a, b)] = std::min(a, b);
        }
    std::vector<std::uint8_t> held(total, 0);
    for (std::size_t n = 0; n < total; ++n)
        if (plan.unknown[n] == -1) held[static_cast<std::size_t>(root(static_cast<std::int32_t>(n)))] = 1;
    for (std::size_t n = 0; n < static_cast<std::size_t>(plan.num_points); ++n)
        if (plan.unknown[n] >= 0 && !held[static_cast<std::size_t>(root(static_cast<std::int32_t>(n)))])
            throw MeshError("laplacian: node " + std::to_string(n) +
                                " lies in a part of the mesh that no boundary node holds (cells joined to no marker): "
                                "its displacement is undetermined",
                            {}, static_cast<NodeId>(n));
}

}  // namespace

std::size_t check_laplacian_inputs(int dim, std::span<const double> points, const ElementList& cells,
                                   const BoundarySet& boundary, const LaplacianOptions& options,
                                   std::string_view who) {
    const std::string w(who);
    const std::size_t num_points = check_points_and_boundary(w, dim, points, boundary);
    if (!(options.increments >= 1 && options.increments <= 64))
        throw Error(w + ": increments must be 1 to 64, got " + std::to_string(options.increments));
    if (!(options.max_increments >= options.increments && options.max_increments <= 64))
        throw Error(w + ": max_increments must be increments to 64, got " + std::to_string(options.max_increments));
    if (!(options.stiffness_exponent >= 0 && options.stiffness_exponent <= 4))
        throw Error(w + ": the stiffness exponent must be 0 to 4, got " +
                    std::to_string(options.stiffness_exponent));
    if (!(options.poisson_ratio >= 0 && options.poisson_ratio <= 0.45))
        throw Error(w + ": Poisson's ratio must be 0 to 0.45, got " + std::to_string(options.poisson_ratio));
    if (cells.empty())
        throw MeshError(w + ": the mesh has no cells (the method solves on the mesh's cells)");
    if (cells.size() > static_cast<std::size_t>(std::numeric_limits<std::int32_t>::max() / 8))
        throw MeshError(w + ": too many cells (" + std::to_string(cells.size()) + ")");
    for (std::size_t c = 0; c < cells.size(); ++c) {
        if (cell_dimension(cells.types[c]) != dim)
            throw MeshError(w + ": cell " + std::to_string(c) + " is a " +
                            std::string(cell_type_name(cells.types[c])) + ", not a " + std::to_string(dim) +
                            "D cell");
        for (NodeId n : cells.nodes_of(c))
            if (n < 0 || static_cast<std::size_t>(n) >= num_points)
                throw MeshError(w + ": cell " + std::to_string(c) + " has node " + std::to_string(n) +
                                    ", out of range (the mesh has " + std::to_string(num_points) + " points)",
                                {}, n);
        const auto [f0, f1] = cells.faces_of(c);
        for (std::int64_t f = f0; f < f1; ++f)
            for (NodeId n : cells.face_nodes_of(f))
                if (std::find(cells.nodes_of(c).begin(), cells.nodes_of(c).end(), n) == cells.nodes_of(c).end())
                    throw MeshError(w + ": a face of cell " + std::to_string(c) + " has node " + std::to_string(n) +
                                        ", not one of the cell's nodes",
                                    {}, n);
    }
    return num_points;
}

LaplacianPlan prepare_laplacian(int dim, std::span<const double> points, const ElementList& cells,
                                const BoundarySet& boundary, const LaplacianOptions& options) {
    const std::size_t num_points = check_laplacian_inputs(dim, points, cells, boundary, options, "laplacian");
    LaplacianPlan plan;
    plan.dim = dim;
    plan.num_points = static_cast<std::int64_t>(num_points);
    plan.options = options;
    plan.boundary_nodes = boundary.nodes;
    plan.boundary_moving = boundary.moving;
    plan.num_cells = static_cast<std::int64_t>(cells.size());
    const auto next_centre = [&] { return static_cast<std::int32_t>(num_points + plan.centre_start.size() - 1); };
    const auto add_centre = [&](std::span<const NodeId> of) {
        const std::int32_t id = next_centre();
        plan.centre_node.insert(plan.centre_node.end(), of.begin(), of.end());
        plan.centre_start.push_back(static_cast<std::int64_t>(plan.centre_node.size()));
        return id;
    };

    // The quadrilateral faces of 3D cells, matched by their sorted corners:
    // one centre per distinct face, shared by its cells.
    std::vector<QuadFace> quads;
    const auto add_quad = [&](std::size_t c, std::array<NodeId, 4> corners) {
        QuadFace q{corners, static_cast<std::int32_t>(c), corners};
        std::sort(q.key.begin(), q.key.end());
        quads.push_back(q);
    };
    if (dim == 3)
        for (std::size_t c = 0; c < cells.size(); ++c) {
            const auto nodes = cells.nodes_of(c);
            for (const Face& f : faces_of(cells.types[c]))
                if (f[3] >= 0) add_quad(c, {nodes[f[0]], nodes[f[1]], nodes[f[2]], nodes[f[3]]});
            const auto [f0, f1] = cells.faces_of(c);  // a polyhedron's
            for (std::int64_t f = f0; f < f1; ++f)
                if (const auto ring = cells.face_nodes_of(f); ring.size() == 4) add_quad(c, {ring[0], ring[1], ring[2], ring[3]});
        }
    std::sort(quads.begin(), quads.end(), [](const QuadFace& a, const QuadFace& b) {
        return a.key != b.key ? a.key < b.key : a.cell < b.cell;
    });
    // Per quad entry, its face centre; a face of one cell whose corners are
    // all boundary nodes is a boundary face: its centre is given.
    std::vector<std::int32_t> quad_centre(quads.size());
    std::vector<std::uint8_t> centre_given;  // per centre
    const auto on_boundary = [&](NodeId n) {
        return std::binary_search(boundary.nodes.begin(), boundary.nodes.end(), n);
    };
    for (std::size_t i = 0; i < quads.size();) {
        std::size_t j = i;
        while (j < quads.size() && quads[j].key == quads[i].key) ++j;
        const std::int32_t centre = add_centre(quads[i].corners);
        const bool given = j - i == 1 && std::all_of(quads[i].key.begin(), quads[i].key.end(), on_boundary);
        centre_given.push_back(given ? 1 : 0);
        for (std::size_t k = i; k < j; ++k) quad_centre[k] = centre;
        i = j;
    }
    // The quad entries of each cell, in the order faces_of lists them.
    std::vector<std::int32_t> quad_of_cell_first(cells.size() + 1, 0);
    std::vector<std::int32_t> quad_index(quads.size());
    {
        for (const QuadFace& q : quads) ++quad_of_cell_first[static_cast<std::size_t>(q.cell) + 1];
        for (std::size_t c = 0; c < cells.size(); ++c) quad_of_cell_first[c + 1] += quad_of_cell_first[c];
        std::vector<std::int32_t> fill(quad_of_cell_first.begin(), quad_of_cell_first.end() - 1);
        // quads sorted by key: find each cell's faces back by their corners.
        for (std::size_t k = 0; k < quads.size(); ++k)
            quad_index[static_cast<std::size_t>(fill[quads[k].cell]++)] = static_cast<std::int32_t>(k);
    }

    // A polyhedron's faces of more than 4 nodes (only polyhedra have them):
    // one centre per distinct face too, given on the boundary.
    std::map<std::vector<NodeId>, std::int32_t> polygon_centre;
    if (cells.has_faces()) {
        std::map<std::vector<NodeId>, std::pair<int, std::vector<NodeId>>> uses;  // sorted ring -> (cells, a ring)
        for (std::size_t c = 0; c < cells.size(); ++c) {
            const auto [f0, f1] = cells.faces_of(c);
            for (std::int64_t f = f0; f < f1; ++f) {
                const auto ring = cells.face_nodes_of(f);
                if (ring.size() <= 4) continue;
                std::vector<NodeId> key(ring.begin(), ring.end());
                std::sort(key.begin(), key.end());
                auto& use = uses[key];
                if (use.first++ == 0) use.second.assign(ring.begin(), ring.end());
            }
        }
        for (const auto& [key, use] : uses) {
            polygon_centre[key] = add_centre(use.second);
            centre_given.push_back(use.first == 1 && std::all_of(key.begin(), key.end(), on_boundary) ? 1 : 0);
        }
    }

    const auto add_simplex = [&](std::size_t cell, std::initializer_list<std::int32_t> ids) {
        plan.simplices.insert(plan.simplices.end(), ids.begin(), ids.end());
        plan.simplex_cell.push_back(static_cast<std::int32_t>(cell));
    };
    for (std::size_t c = 0; c < cells.size(); ++c) {
        const auto nodes = cells.nodes_of(c);
        const CellType t = cells.types[c];
        if (is_simplex(dim, t)) {
            plan.simplices.insert(plan.simplices.end(), nodes.begin(), nodes.end());
            plan.simplex_cell.push_back(static_cast<std::int32_t>(c));
            continue;
        }
        const std::int32_t centre = add_centre(nodes);
        centre_given.push_back(0);
        if (t == CellType::polyhedron) {
            // Each face: a triangle with the centre, a quadrilateral and a
            // larger polygon with their shared face centre too.
            const auto [f0, f1] = cells.faces_of(c);
            for (std::int64_t f = f0; f < f1; ++f) {
                const auto ring = cells.face_nodes_of(f);
                if (ring.size() == 3) {
                    add_simplex(c, {ring[0], ring[1], ring[2], centre});
                    continue;
                }
                std::int32_t fc = -1;
                if (ring.size() == 4) {
                    const std::array<NodeId, 4> face{ring[0], ring[1], ring[2], ring[3]};
                    for (std::int32_t k = quad_of_cell_first[c]; k < quad_of_cell_first[c + 1]; ++k)
                        if (quads[static_cast<std::size_t>(quad_index[k])].corners == face) fc = quad_centre[quad_index[k]];
                } else {
                    std::vector<NodeId> key(ring.begin(), ring.end());
                    std::sort(key.begin(), key.end());
                    fc = polygon_centre.at(key);
                }
                for (std::size_t k = 0; k < ring.size(); ++k) add_simplex(c, {ring[k], ring[(k + 1) % ring.size()], fc, centre});
            }
            continue;
        }
        for (const auto& corner : corner_neighbours(t))
            for (int k = 0; k <= dim; ++k) plan.corners.push_back(nodes[corner[k]]);
        if (dim == 2) {  // a quadrilateral: a triangle on each edge
            for (std::size_t k = 0; k < nodes.size(); ++k) add_simplex(c, {nodes[k], nodes[(k + 1) % nodes.size()], centre});
            continue;
        }
        for (const Face& f : faces_of(t)) {
            if (f[3] < 0) {
                add_simplex(c, {nodes[f[0]], nodes[f[1]], nodes[f[2]], centre});
                continue;
            }
            const std::array<NodeId, 4> face{nodes[f[0]], nodes[f[1]], nodes[f[2]], nodes[f[3]]};
            std::int32_t fc = -1;
            for (std::int32_t k = quad_of_cell_first[c]; k < quad_of_cell_first[c + 1]; ++k)
                if (quads[static_cast<std::size_t>(quad_index[k])].corners == face) fc = quad_centre[quad_index[k]];
            for (int k = 0; k < 4; ++k) add_simplex(c, {face[k], face[(k + 1) % 4], fc, centre});
        }
    }

    // Unknowns: volume nodes that a cell uses, and the centres not given.
    const std::size_t total = num_points + centre_given.size();
    std::vector<std::uint8_t> used(total, 0);
    for (std::int32_t n : plan.simplices) used[static_cast<std::size_t>(n)] = 1;
    plan.unknown.assign(total, -2);
    std::int32_t next = 0;
    for (std::size_t n = 0; n < total; ++n) {
        const bool given = n < num_points ? on_boundary(static_cast<NodeId>(n)) : centre_given[n - num_points] != 0;
        if (given) plan.unknown[n] = -1;
        else if (used[n]) plan.unknown[n] = next++;
    }
    plan.num_unknowns = next;
    check_every_part_held(plan);
    return plan;
}

std::size_t plan_bytes(const LaplacianPlan& p) {
    return bytes_of(p.boundary_nodes) + bytes_of(p.boundary_moving) + bytes_of(p.simplices) + bytes_of(p.corners) +
           bytes_of(p.simplex_cell) + bytes_of(p.centre_start) + bytes_of(p.centre_node) + bytes_of(p.unknown);
}

}  // namespace dgwarp
