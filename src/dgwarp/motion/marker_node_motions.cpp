#include "dgwarp/motion/marker_node_motions.hpp"

#include <algorithm>
#include <cassert>
#include <map>
#include <numeric>
#include <sstream>
#include <string>

#include "dgwarp/core/error.hpp"

namespace dgwarp {

namespace {

constexpr std::size_t npos = static_cast<std::size_t>(-1);

std::string prefix(std::string_view where) { return where.empty() ? std::string() : std::string(where) + ": "; }

std::string vec_text(const Vec3& v) {
    std::ostringstream s;
    s << "(" << v[0] << ", " << v[1] << ", " << v[2] << ")";
    return s.str();
}

template <class Value>
std::string table_name(const NodeTable<Value>& t) {
    return t.source.empty() ? std::string("the node table") : t.source;
}

template <class Value>
std::string at_line(const NodeTable<Value>& t, std::size_t entry) {
    return t.lines.empty() ? std::string() : " (line " + std::to_string(t.lines[entry]) + ")";
}

/// The table of a table-based motion, or nullptr.
template <class Value>
const NodeTable<Value>* table_of(const MarkerMotion& m);
template <>
const NodeTable<Vec3>* table_of<Vec3>(const MarkerMotion& m) {
    if (const auto* d = std::get_if<PrescribedDisplacements>(&m)) return &d->displacements;
    if (const auto* p = std::get_if<PrescribedPositions>(&m)) return &p->positions;
    return nullptr;
}
template <>
const NodeTable<NodeMotion>* table_of<NodeMotion>(const MarkerMotion& m) {
    if (const auto* n = std::get_if<PrescribedNodeMotions>(&m)) return &n->motions;
    return nullptr;
}

/// Finds table entries by node id.
template <class Value>
struct TableLookup {
    const NodeTable<Value>* table = nullptr;
    std::vector<std::size_t> order;  // entry indices sorted by node id

    explicit TableLookup(const NodeTable<Value>& t) : table(&t), order(t.nodes.size()) {
        std::iota(order.begin(), order.end(), std::size_t{0});
        std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return t.nodes[a] < t.nodes[b]; });
    }
    std::size_t find(NodeId node) const {
        const auto it = std::lower_bound(order.begin(), order.end(), node,
                                         [&](std::size_t e, NodeId n) { return table->nodes[e] < n; });
        return it != order.end() && table->nodes[*it] == node ? *it : npos;
    }
};

/// Checks a table against the markers that use it (see the header).
template <class Value>
void check_table(const Mesh& mesh, const NodeTable<Value>& table, const std::vector<std::size_t>& users,
                 std::span<const std::vector<NodeId>> marker_nodes, const TableLookup<Value>& lookup,
                 std::string_view where) {
    const std::string& first_user = mesh.markers[users[0]].name;
    std::string user_names;
    for (std::size_t m : users) user_names += (user_names.empty() ? "'" : ", '") + mesh.markers[m].name + "'";

    if (mesh.dim == 3 && table.components == 2)
        throw MeshError(prefix(where) + table_name(table) + " gives 2 coordinates per node, but the mesh is 3D (marker " +
                            user_names + ")",
                        first_user);
    const auto num_points = static_cast<std::int64_t>(mesh.num_points());
    for (std::size_t e = 0; e < table.nodes.size(); ++e) {
        const NodeId node = table.nodes[e];
        if (node < 0 || node >= num_points)
            throw MeshError(prefix(where) + "node " + std::to_string(node) + " in " + table_name(table) + at_line(table, e) +
                                " is not a node of the mesh, which has " + std::to_string(num_points) +
                                " nodes (ids 0-based)",
                            first_user, node);
        const bool on_a_user = std::any_of(users.begin(), users.end(), [&](std::size_t m) {
            return std::binary_search(marker_nodes[m].begin(), marker_nodes[m].end(), node);
        });
        if (!on_a_user)
            throw MeshError(prefix(where) + "node " + std::to_string(node) + " in " + table_name(table) + at_line(table, e) +
                                " is not on " + (users.size() == 1 ? "marker " : "any of the markers ") + user_names +
                                (users.size() == 1 ? "" : " that use the file"),
                            first_user, node);
    }
    for (std::size_t m : users) {
        std::size_t missing = 0;
        NodeId first_missing = -1;
        for (NodeId node : marker_nodes[m])
            if (lookup.find(node) == npos && missing++ == 0) first_missing = node;
        if (missing > 0)
            throw MeshError(prefix(where) + std::to_string(missing) + " of the " + std::to_string(marker_nodes[m].size()) +
                                " nodes of marker '" + mesh.markers[m].name + (missing == 1 ? "' is" : "' are") +
                                " not in " + table_name(table) +
                                (missing == 1 ? " (node " : " (first: node ") + std::to_string(first_missing) + ")",
                            mesh.markers[m].name, first_missing);
    }
}

/// Groups the markers whose motions use the same node table.
template <class Value>
std::map<std::string, std::vector<std::size_t>> table_users(std::span<const MarkerMotion* const> motions) {
    std::map<std::string, std::vector<std::size_t>> users;
    for (std::size_t m = 0; m < motions.size(); ++m) {
        const NodeTable<Value>* t = table_of<Value>(*motions[m]);
        if (!t) continue;
        std::ostringstream key;
        key << motions[m]->index() << ':';
        if (t->source.empty()) key << static_cast<const void*>(t);
        else key << t->source;
        users[key.str()].push_back(m);
    }
    return users;
}

/// Checks every table of kind Value and fills the motions of its users' nodes.
template <class Value, class ToMotion>
void table_motions(const Mesh& mesh, std::span<const std::vector<NodeId>> marker_nodes,
                   std::span<const MarkerMotion* const> motions, std::string_view where, ToMotion to_motion,
                   std::vector<std::vector<NodeMotion>>& out) {
    for (const auto& [key, users] : table_users<Value>(motions)) {
        const MarkerMotion& motion = *motions[users[0]];
        const NodeTable<Value>& table = *table_of<Value>(motion);
        const TableLookup<Value> lookup(table);
        check_table(mesh, table, users, marker_nodes, lookup, where);
        for (std::size_t m : users) {
            out[m].resize(marker_nodes[m].size());
            for (std::size_t j = 0; j < marker_nodes[m].size(); ++j) {
                const NodeId node = marker_nodes[m][j];
                out[m][j] = to_motion(motion, table.values[lookup.find(node)], node);
            }
        }
    }
}

/// Checks 2D motions stay in the plane: no z translation, rotation about z only.
void check_planar(const Mesh& mesh, std::span<const std::vector<NodeId>> marker_nodes,
                  const std::vector<std::vector<NodeMotion>>& motions, std::string_view where) {
    for (std::size_t m = 0; m < motions.size(); ++m)
        for (std::size_t j = 0; j < motions[m].size(); ++j) {
            const NodeMotion& nm = motions[m][j];
            if (nm.translation[2] == 0 && nm.rotation[0] == 0 && nm.rotation[1] == 0) continue;
            const NodeId node = marker_nodes[m][j];
            throw MeshError(prefix(where) + "marker '" + mesh.markers[m].name +
                                "': a 2D mesh moves in the xy plane and rotates about z only, but node " +
                                std::to_string(node) + " gets translation " + vec_text(nm.translation) +
                                " and rotation vector " + vec_text(nm.rotation),
                            mesh.markers[m].name, node);
        }
}

}  // namespace

std::vector<std::vector<NodeMotion>> marker_node_motions(const Mesh& mesh,
                                                         std::span<const std::vector<NodeId>> marker_nodes,
                                                         std::span<const MarkerMotion* const> motions,
                                                         double time, std::string_view where) {
    assert(marker_nodes.size() == mesh.markers.size() && motions.size() == mesh.markers.size());
    std::vector<std::vector<NodeMotion>> out(motions.size());
    for (std::size_t m = 0; m < motions.size(); ++m) {
        const MarkerMotion& motion = *motions[m];
        if (const auto* r = std::get_if<RigidMotion>(&motion)) out[m].assign(marker_nodes[m].size(), r->motion);
        else if (const auto* p = std::get_if<PeriodicMotion>(&motion))
            out[m].assign(marker_nodes[m].size(), periodic_motion_at(*p, time));
    }
    const auto dim = static_cast<std::size_t>(mesh.dim);
    table_motions<Vec3>(mesh, marker_nodes, motions, where,
                        [&](const MarkerMotion& motion, const Vec3& value, NodeId node) {
                            NodeMotion nm;
                            if (std::holds_alternative<PrescribedDisplacements>(motion)) {
                                nm.translation = value;
                            } else {  // new position: t = p - x
                                const double* x = mesh.points.data() + static_cast<std::size_t>(node) * dim;
                                for (std::size_t i = 0; i < 3; ++i) nm.translation[i] = value[i] - (i < dim ? x[i] : 0.0);
                            }
                            return nm;
                        },
                        out);
    table_motions<NodeMotion>(mesh, marker_nodes, motions, where,
                              [](const MarkerMotion&, const NodeMotion& value, NodeId) { return value; }, out);
    if (mesh.dim == 2) check_planar(mesh, marker_nodes, out, where);
    return out;
}

}  // namespace dgwarp
