#include "dgwarp/cases/gmsh_session.hpp"

#include <gmsh.h>

#include <cstddef>
#include <exception>
#include <mutex>
#include <unordered_map>

#include "dgwarp/core/error.hpp"

namespace dgwarp::detail {

void with_gmsh(const std::string& what, int threads, const std::function<void()>& build) {
    // Gmsh's model and options are process-wide: one session at a time,
    // whatever thread asks (Python releases the GIL around dgwarp.case).
    static std::mutex one_session;
    const std::lock_guard<std::mutex> lock(one_session);
    gmsh::initialize();
    try {
        gmsh::option::setNumber("General.Terminal", 0);
        gmsh::option::setNumber("General.NumThreads", threads);
        build();
    } catch (const Error&) {
        gmsh::finalize();
        throw;
    } catch (const std::exception& e) {
        gmsh::finalize();
        throw MeshError(what + ": Gmsh failed: " + e.what());
    } catch (...) {  // Gmsh 4.8 may throw a plain value; its message is its last error
        std::string error;
        try {
            gmsh::logger::getLastError(error);
        } catch (...) {
            error.clear();
        }
        gmsh::finalize();
        throw MeshError(what + ": Gmsh failed" + (error.empty() ? std::string() : ": " + error));
    }
    gmsh::finalize();
}

namespace {

/// Signed area (2D) or 6 × signed volume (3D) of a simplex.
double signed_measure(int dim, const std::vector<double>& p, std::span<const NodeId> n) {
    auto x = [&](NodeId i, int c) { return p[static_cast<std::size_t>(i) * dim + c]; };
    if (dim == 2)
        return (x(n[1], 0) - x(n[0], 0)) * (x(n[2], 1) - x(n[0], 1)) -
               (x(n[2], 0) - x(n[0], 0)) * (x(n[1], 1) - x(n[0], 1));
    double a[3], b[3], c[3];
    for (int k = 0; k < 3; ++k) {
        a[k] = x(n[1], k) - x(n[0], k);
        b[k] = x(n[2], k) - x(n[0], k);
        c[k] = x(n[3], k) - x(n[0], k);
    }
    return a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0]) + a[2] * (b[0] * c[1] - b[1] * c[0]);
}

}  // namespace

Mesh mesh_from_gmsh(int dim, const std::vector<std::pair<std::string, std::vector<int>>>& markers) {
    std::vector<std::size_t> tags;
    std::vector<double> coords, parametric;
    gmsh::model::mesh::getNodes(tags, coords, parametric, -1, -1, false, false);
    Mesh mesh;
    mesh.dim = dim;
    mesh.points.reserve(tags.size() * dim);
    std::unordered_map<std::size_t, NodeId> index;
    index.reserve(tags.size());
    for (std::size_t i = 0; i < tags.size(); ++i) {
        index[tags[i]] = static_cast<NodeId>(i);
        for (int k = 0; k < dim; ++k) mesh.points.push_back(coords[3 * i + k]);
    }
    const int cell_type = dim == 2 ? 2 : 4, face_type = dim == 2 ? 1 : 2;  // Gmsh: triangle, tet, line
    const CellType cell = dim == 2 ? CellType::triangle : CellType::tetrahedron;
    const CellType face = dim == 2 ? CellType::line : CellType::triangle;
    std::vector<std::size_t> element_tags, node_tags;
    gmsh::model::mesh::getElementsByType(cell_type, element_tags, node_tags, -1);
    const std::size_t per = static_cast<std::size_t>(dim) + 1;
    mesh.cells.reserve(element_tags.size(), static_cast<int>(per));
    std::vector<NodeId> nodes(per);
    for (std::size_t e = 0; e < element_tags.size(); ++e) {
        for (std::size_t k = 0; k < per; ++k) nodes[k] = index.at(node_tags[e * per + k]);
        if (signed_measure(dim, mesh.points, nodes) < 0) std::swap(nodes[0], nodes[1]);
        mesh.cells.push_back(cell, nodes);
    }
    if (dim == 2) {  // quadrilaterals (boundary layers), counter-clockwise
        std::vector<std::size_t> quad_tags, quad_nodes;  // fresh: Gmsh 4.8 may leave earlier contents
        gmsh::model::mesh::getElementsByType(3, quad_tags, quad_nodes, -1);
        std::vector<NodeId> quad(4);
        for (std::size_t e = 0; e < quad_tags.size() && quad_nodes.size() == 4 * quad_tags.size(); ++e) {
            for (std::size_t k = 0; k < 4; ++k) quad[k] = index.at(quad_nodes[e * 4 + k]);
            if (signed_measure(2, mesh.points, quad) < 0) std::swap(quad[1], quad[3]);
            mesh.cells.push_back(CellType::quadrilateral, quad);
        }
    }
    for (const auto& [name, entities] : markers) {
        Marker m{name, {}};
        for (int entity : entities) {
            std::vector<int> types;
            std::vector<std::vector<std::size_t>> type_tags, type_nodes;
            gmsh::model::mesh::getElements(types, type_tags, type_nodes, dim - 1, entity);
            const std::size_t fper = static_cast<std::size_t>(dim);
            std::vector<NodeId> face_nodes(fper);
            for (std::size_t t = 0; t < types.size(); ++t) {
                if (types[t] != face_type) continue;
                for (std::size_t e = 0; e < type_tags[t].size(); ++e) {
                    for (std::size_t k = 0; k < fper; ++k) face_nodes[k] = index.at(type_nodes[t][e * fper + k]);
                    m.elements.push_back(face, face_nodes);
                }
            }
        }
        mesh.markers.push_back(std::move(m));
    }
    return mesh;
}

}  // namespace dgwarp::detail
