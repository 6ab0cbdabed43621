#include "dgwarp/mesh/planar_case.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

namespace dgwarp {

namespace {

using P3 = std::array<double, 3>;

P3 point_of(const Mesh& mesh, NodeId n) {
    const double* p = mesh.points.data() + static_cast<std::size_t>(n) * 3;
    return {p[0], p[1], p[2]};
}

double dot(const P3& a, const P3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

P3 cross(const P3& a, const P3& b) {
    return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}

/// Newell's normal of a face (not normalised).
P3 face_normal(const Mesh& mesh, std::span<const NodeId> face) {
    P3 n{};
    for (std::size_t i = 0; i < face.size(); ++i) {
        const P3 a = point_of(mesh, face[i]), b = point_of(mesh, face[(i + 1) % face.size()]);
        n[0] += (a[1] - b[1]) * (a[2] + b[2]);
        n[1] += (a[2] - b[2]) * (a[0] + b[0]);
        n[2] += (a[0] - b[0]) * (a[1] + b[1]);
    }
    return n;
}

/// The edges of a hexahedron and of a prism (VTK node order); those across
/// the layer are the ones with a node on each plane.
constexpr int hex_edges[12][2] = {{0, 1}, {1, 2}, {2, 3}, {3, 0}, {4, 5}, {5, 6},
                                  {6, 7}, {7, 4}, {0, 4}, {1, 5}, {2, 6}, {3, 7}};
constexpr int prism_edges[9][2] = {{0, 1}, {1, 2}, {2, 0}, {3, 4}, {4, 5}, {5, 3}, {0, 3}, {1, 4}, {2, 5}};

/// A face by its sorted nodes (any number: a polyhedron's face on a plane is a polygon).
using FaceKey = std::vector<NodeId>;

FaceKey key_of(std::span<const NodeId> nodes) {
    FaceKey k(nodes.begin(), nodes.end());
    std::sort(k.begin(), k.end());
    return k;
}

PlanarCaseResult not_planar(std::string why) { return {std::nullopt, std::move(why)}; }

}  // namespace

namespace {

P3 unit(const P3& a) {
    const double l = std::sqrt(dot(a, a));
    return {a[0] / l, a[1] / l, a[2] / l};
}

P3 scaled(const P3& a, double s) { return {a[0] * s, a[1] * s, a[2] * s}; }
P3 plus(const P3& a, const P3& b) { return {a[0] + b[0], a[1] + b[1], a[2] + b[2]}; }
P3 minus(const P3& a, const P3& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }

/// A marker's normal: the sum of its faces' area vectors, each turned to the
/// first's side (so that a marker of two parallel planes has one); zero when
/// it has no face of non-zero area.
P3 marker_normal(const Mesh& mesh, const Marker& marker) {
    P3 sum{}, first{};
    for (std::size_t f = 0; f < marker.elements.size(); ++f) {
        const P3 n = face_normal(mesh, marker.elements.nodes_of(f));
        if (dot(first, first) == 0) first = n;
        sum = plus(sum, dot(n, first) < 0 ? scaled(n, -1) : n);
    }
    return sum;
}

}  // namespace

PlanarCaseResult find_planar_case(const Mesh& mesh, std::span<const std::size_t> plane_markers,
                                  const std::string& axis_name) {
    if (mesh.dim != 3 || plane_markers.empty()) return not_planar("not a 3D mesh with plane markers");
    const BoundingBox box = bounding_box(mesh);
    const double diagonal = std::hypot(box.max[0] - box.min[0], box.max[1] - box.min[1], box.max[2] - box.min[2]);
    const double tolerance = 1e-6 * diagonal;
    const std::size_t num = mesh.num_points();
    PlanarCase planar;
    std::vector<char> is_plane_marker(mesh.markers.size(), 0);
    std::vector<P3> normals;
    for (std::size_t m : plane_markers) {
        is_plane_marker[m] = 1;
        planar.plane_markers.push_back(mesh.markers[m].name);
        const P3 n = marker_normal(mesh, mesh.markers[m]);
        if (!(dot(n, n) > 0)) return not_planar("marker '" + mesh.markers[m].name + "' has no face of non-zero area");
        normals.push_back(unit(n));
    }
    const bool parallel = std::all_of(normals.begin(), normals.end(),
                                      [&](const P3& n) { return std::abs(dot(n, normals[0])) >= 1 - 1e-6; });
    std::vector<std::uint8_t>& side = planar.side;
    side.assign(num, 0);
    const auto off_plane = [&](NodeId v, std::size_t m) {
        return not_planar("node " + std::to_string(v) + " of marker '" + mesh.markers[m].name +
                          "' is on neither of the two planes");
    };
    if (parallel) {
        // Two parallel planes: n a coordinate axis when it is one; the first plane the lower.
        P3 n = normals[0];
        for (int k = 0; k < 3; ++k)
            if (std::abs(n[static_cast<std::size_t>(k)]) > 1 - 1e-6) {
                n = {0, 0, 0};
                n[static_cast<std::size_t>(k)] = 1;
                planar.axis = k;
            }
        if (planar.axis < 0) {
            const auto big = std::max_element(n.begin(), n.end(), [](double a, double b) { return std::abs(a) < std::abs(b); });
            if (*big < 0) n = scaled(n, -1);
        }
        double low = INFINITY, high = -INFINITY;
        for (std::size_t m : plane_markers)
            for (NodeId v : mesh.markers[m].elements.nodes) {
                low = std::min(low, dot(n, point_of(mesh, v)));
                high = std::max(high, dot(n, point_of(mesh, v)));
            }
        if (!(high - low > 2 * tolerance)) return not_planar("the plane markers' faces lie in one plane");
        for (std::size_t m : plane_markers)
            for (NodeId v : mesh.markers[m].elements.nodes) {
                const double d = dot(n, point_of(mesh, v));
                const std::uint8_t s = std::abs(d - low) <= tolerance ? 1 : std::abs(d - high) <= tolerance ? 2 : 0;
                if (s == 0) return off_plane(v, m);
                side[static_cast<std::size_t>(v)] = s;
            }
        planar.normal = planar.normal_second = n;
        planar.thickness = high - low;
        if (planar.axis >= 0) {
            const auto k = static_cast<std::size_t>(planar.axis);
            planar.u[(k + 1) % 3] = 1;
            planar.v[(k + 2) % 3] = 1;
        } else {
            // u: the coordinate axis least along n, made orthogonal to it; v = n × u.
            const auto small = static_cast<std::size_t>(
                std::min_element(n.begin(), n.end(), [](double a, double b) { return std::abs(a) < std::abs(b); }) -
                n.begin());
            P3 e{};
            e[small] = 1;
            planar.u = unit(minus(e, scaled(n, dot(e, n))));
            planar.v = cross(n, planar.u);
        }
        planar.v_second = planar.v;
    } else {
        // A wedge: two markers, a plane each, meeting at the axis.
        if (plane_markers.size() != 2)
            return not_planar("the plane markers are neither parallel nor the two planes of a wedge");
        planar.wedge = true;
        const P3 na = normals[0], nb = normals[1];  // outward
        double offset[2] = {0, 0};
        for (std::size_t i = 0; i < 2; ++i) {
            const Marker& marker = mesh.markers[plane_markers[i]];
            const P3& n = i == 0 ? na : nb;
            offset[i] = dot(n, point_of(mesh, marker.elements.nodes.front()));
            for (NodeId v : marker.elements.nodes) {
                if (std::abs(dot(n, point_of(mesh, v)) - offset[i]) > tolerance) return off_plane(v, plane_markers[i]);
                side[static_cast<std::size_t>(v)] |= static_cast<std::uint8_t>(i + 1);
            }
        }
        // The axis: the planes' common line, through o.
        const double c = dot(na, nb);
        planar.origin = scaled(plus(scaled(na, offset[0] - offset[1] * c), scaled(nb, offset[1] - offset[0] * c)),
                               1 / (1 - c * c));
        P3 a = unit(cross(na, nb));
        for (std::size_t k = 0; k < 3; ++k)  // a coordinate axis (the usual case): exactly
            if (std::abs(a[k]) > 1 - 1e-12) {
                const double sign = a[k] > 0 ? 1 : -1;
                a = {0, 0, 0};
                a[k] = sign;
            }
        // Into the mesh, and exactly normal to the (maybe snapped) axis.
        planar.normal = unit(scaled(minus(na, scaled(a, dot(na, a))), -1));
        planar.normal_second = unit(scaled(minus(nb, scaled(a, dot(nb, a))), -1));
        P3 v = unit(cross(planar.normal, a));
        // v away from the axis, toward the first plane's nodes.
        double mean = 0;
        for (std::size_t p = 0; p < num; ++p)
            if (side[p] == 1) mean += dot(minus(point_of(mesh, static_cast<NodeId>(p)), planar.origin), v);
        if (mean < 0) {
            a = scaled(a, -1);
            v = scaled(v, -1);
        }
        planar.u = a;
        planar.v = v;
        P3 w = unit(cross(nb, a));
        if (dot(w, v) < 0) w = scaled(w, -1);
        planar.v_second = w;
        planar.thickness = std::acos(std::clamp(dot(v, w), -1.0, 1.0));
    }
    for (std::size_t v = 0; v < num; ++v)
        if (side[v] == 0) return not_planar("node " + std::to_string(v) + " is on no plane marker");

    // The first plane's faces, by their sorted nodes.
    std::vector<std::pair<FaceKey, std::pair<std::size_t, std::size_t>>> faces;  // key, (marker, face)
    for (std::size_t m : plane_markers) {
        const ElementList& list = mesh.markers[m].elements;
        for (std::size_t f = 0; f < list.size(); ++f) {
            const auto nodes = list.nodes_of(f);
            if (std::all_of(nodes.begin(), nodes.end(), [&](NodeId v) { return (side[static_cast<std::size_t>(v)] & 1) != 0; }))
                faces.push_back({key_of(nodes), {m, f}});
        }
    }
    std::sort(faces.begin(), faces.end());

    // Cells: their face on the first plane, and their edges across the layer.
    std::vector<NodeId> twin(num, -1);
    std::vector<NodeId> cell_nodes;
    for (std::size_t c = 0; c < mesh.cells.size(); ++c) {
        const CellType type = mesh.cells.types[c];
        const auto nodes = mesh.cells.nodes_of(c);
        const std::string cell = "cell " + std::to_string(c);
        if (type != CellType::hexahedron && type != CellType::prism && type != CellType::polyhedron)
            return not_planar(cell + " is a " + std::string(cell_type_name(type)) +
                              ", not a hexahedron, prism or polyhedron");
        cell_nodes.clear();
        for (NodeId v : nodes)
            if (side[static_cast<std::size_t>(v)] & 1) cell_nodes.push_back(v);
        if (cell_nodes.size() < 3 || (type != CellType::polyhedron && cell_nodes.size() > 4))
            return not_planar(cell + " does not span the layer");
        const FaceKey key = key_of(cell_nodes);
        const auto it = std::lower_bound(faces.begin(), faces.end(), key,
                                         [](const auto& e, const FaceKey& k) { return e.first < k; });
        if (it == faces.end() || it->first != key) return not_planar(cell + " has no face on the first plane");
        // The face points out of the mesh: reversed, it turns counter-clockwise about the normal into it.
        const auto face = mesh.markers[it->second.first].elements.nodes_of(it->second.second);
        std::vector<NodeId> reversed(face.rbegin(), face.rend());
        planar.mesh.cells.push_back(polygon_type(face.size()), reversed);
        const auto edge = [&](int a, int b) -> bool {
            NodeId p = nodes[static_cast<std::size_t>(a)], q = nodes[static_cast<std::size_t>(b)];
            if (side[static_cast<std::size_t>(p)] == 1) std::swap(p, q);
            if (side[static_cast<std::size_t>(p)] != 2 || side[static_cast<std::size_t>(q)] != 1) return true;
            NodeId& t = twin[static_cast<std::size_t>(p)];  // p on the second plane only, q on the first only
            if (t >= 0 && t != q) return false;
            t = q;
            return true;
        };
        bool ok = true;
        if (type == CellType::hexahedron) {
            for (const auto& e : hex_edges) ok = ok && edge(e[0], e[1]);
        } else if (type == CellType::prism) {
            for (const auto& e : prism_edges) ok = ok && edge(e[0], e[1]);
        } else {  // a polyhedron: the edges of its faces
            const auto position = [&](NodeId v) {
                return static_cast<int>(std::find(nodes.begin(), nodes.end(), v) - nodes.begin());
            };
            const auto [f0, f1] = mesh.cells.faces_of(c);
            for (std::int64_t f = f0; f < f1 && ok; ++f) {
                const auto ring = mesh.cells.face_nodes_of(f);
                for (std::size_t k = 0; k < ring.size() && ok; ++k)
                    ok = edge(position(ring[k]), position(ring[(k + 1) % ring.size()]));
            }
        }
        if (!ok) return not_planar(cell + " joins a node of the second plane to a second node of the first");
    }

    // 2D nodes: the first plane's, in 3D order.
    planar.node_2d.assign(num, -1);
    for (std::size_t v = 0; v < num; ++v)
        if (side[v] & 1) {
            planar.node_2d[v] = static_cast<NodeId>(planar.node_3d.size());
            planar.node_3d.push_back(static_cast<NodeId>(v));
        }
    for (std::size_t v = 0; v < num; ++v)
        if (side[v] == 2) {
            if (twin[v] < 0) return not_planar("node " + std::to_string(v) + " of the second plane is in no cell");
            planar.node_2d[v] = planar.node_2d[static_cast<std::size_t>(twin[v])];
        }
    for (NodeId& v : planar.mesh.cells.nodes) v = planar.node_2d[static_cast<std::size_t>(v)];

    planar.mesh.dim = 2;
    planar.mesh.points.reserve(planar.node_3d.size() * 2);
    for (NodeId v : planar.node_3d) {
        const auto p = planar_point(planar, point_of(mesh, v));
        planar.mesh.points.insert(planar.mesh.points.end(), p.begin(), p.end());
    }

    // The other markers: their faces' edges on the first plane.
    for (std::size_t m = 0; m < mesh.markers.size(); ++m) {
        if (is_plane_marker[m]) continue;
        Marker line{mesh.markers[m].name, {}};
        const ElementList& list = mesh.markers[m].elements;
        for (std::size_t f = 0; f < list.size(); ++f) {
            const auto nodes = list.nodes_of(f);
            std::size_t on_first = 0, at = nodes.size();
            for (std::size_t i = 0; i < nodes.size(); ++i)
                if (side[static_cast<std::size_t>(nodes[i])] & 1) {
                    ++on_first;
                    if (side[static_cast<std::size_t>(nodes[(i + 1) % nodes.size()])] & 1) at = i;
                }
            if (on_first != 2 || at == nodes.size())
                return not_planar("face " + std::to_string(f) + " of marker '" + line.name +
                                  "' has no single edge on the first plane");
            const NodeId edge[2] = {planar.node_2d[static_cast<std::size_t>(nodes[at])],
                                    planar.node_2d[static_cast<std::size_t>(nodes[(at + 1) % nodes.size()])]};
            line.elements.push_back(CellType::line, edge);
        }
        planar.mesh.markers.push_back(std::move(line));
    }

    // A wedge's axis: the 2D boundary edges with both nodes on it, as a marker.
    if (planar.wedge) {
        std::vector<std::pair<std::pair<NodeId, NodeId>, std::pair<NodeId, NodeId>>> edges;  // sorted, as in the cell
        const ElementList& cells = planar.mesh.cells;
        for (std::size_t c = 0; c < cells.size(); ++c) {
            const auto nodes = cells.nodes_of(c);
            for (std::size_t i = 0; i < nodes.size(); ++i) {
                const NodeId a = nodes[i], b = nodes[(i + 1) % nodes.size()];
                edges.push_back({{std::min(a, b), std::max(a, b)}, {a, b}});
            }
        }
        std::sort(edges.begin(), edges.end());
        Marker axis{axis_name, {}};
        for (std::size_t i = 0; i < edges.size(); ++i) {
            const bool single = (i == 0 || edges[i - 1].first != edges[i].first) &&
                                (i + 1 == edges.size() || edges[i + 1].first != edges[i].first);
            const auto [a, b] = edges[i].second;
            if (single && side[static_cast<std::size_t>(planar.node_3d[static_cast<std::size_t>(a)])] == 3 &&
                side[static_cast<std::size_t>(planar.node_3d[static_cast<std::size_t>(b)])] == 3) {
                const NodeId line[2] = {a, b};
                axis.elements.push_back(CellType::line, line);
            }
        }
        if (!axis.elements.empty()) {
            planar.axis_marker = axis_name;
            const auto same = std::find_if(planar.mesh.markers.begin(), planar.mesh.markers.end(),
                                           [&](const Marker& m) { return m.name == axis_name; });
            if (same == planar.mesh.markers.end()) planar.mesh.markers.push_back(std::move(axis));
            else if (same->elements.empty()) *same = std::move(axis);
            else return not_planar("marker '" + axis_name + "' has faces, and the wedge's axis edges need its name");
        }
    }
    return {std::move(planar), {}};
}

std::array<double, 2> planar_point(const PlanarCase& planar, const std::array<double, 3>& x, bool second) {
    if (planar.axis >= 0) {
        const auto k = static_cast<std::size_t>(planar.axis);
        return {x[(k + 1) % 3], x[(k + 2) % 3]};
    }
    const P3 d = minus(x, planar.origin);
    return {dot(d, planar.u), dot(d, second ? planar.v_second : planar.v)};
}

std::array<double, 2> planar_vector(const PlanarCase& planar, const std::array<double, 3>& d, bool second,
                                    double* along_normal) {
    if (along_normal) *along_normal = dot(d, second ? planar.normal_second : planar.normal);
    if (planar.axis >= 0) {
        const auto k = static_cast<std::size_t>(planar.axis);
        return {d[(k + 1) % 3], d[(k + 2) % 3]};
    }
    return {dot(d, planar.u), dot(d, second ? planar.v_second : planar.v)};
}

void lift_points(const PlanarCase& planar, std::span<const double> original, std::span<const double> points_2d,
                 std::span<double> out) {
    const std::size_t num = planar.node_2d.size();
    const std::vector<double>& before = planar.mesh.points;
    for (std::size_t v = 0; v < num; ++v) {
        const auto j = static_cast<std::size_t>(planar.node_2d[v]);
        const double du = points_2d[2 * j] - before[2 * j], dv = points_2d[2 * j + 1] - before[2 * j + 1];
        if (planar.axis >= 0) {
            const auto k = static_cast<std::size_t>(planar.axis);
            const std::size_t a = (k + 1) % 3, b = (k + 2) % 3;
            out[3 * v + k] = original[3 * v + k];
            out[3 * v + a] = original[3 * v + a] == before[2 * j] ? points_2d[2 * j] : original[3 * v + a] + du;
            out[3 * v + b] = original[3 * v + b] == before[2 * j + 1] ? points_2d[2 * j + 1] : original[3 * v + b] + dv;
        } else {
            // A node on a wedge's axis stays on it: its radial displacement is round-off.
            const double radial_motion = planar.side[v] == 3 ? 0 : dv;
            const P3& radial = planar.side[v] == 2 ? planar.v_second : planar.v;
            for (std::size_t c = 0; c < 3; ++c)
                out[3 * v + c] = original[3 * v + c] + du * planar.u[c] + radial_motion * radial[c];
        }
    }
}

}  // namespace dgwarp
