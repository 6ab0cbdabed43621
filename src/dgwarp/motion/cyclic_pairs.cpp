#include "dgwarp/motion/cyclic_pairs.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cassert>
#include <cmath>
#include <deque>
#include <limits>
#include <map>
#include <optional>
#include <string>
#include <utility>

#include "dgwarp/core/error.hpp"
#include "dgwarp/graph/nearest_node.hpp"

namespace dgwarp {

namespace {

using V3 = Eigen::Vector3d;
using M3 = Eigen::Matrix3d;

V3 point3(const Mesh& mesh, NodeId node) {
    const auto dim = static_cast<std::size_t>(mesh.dim);
    const double* x = mesh.points.data() + static_cast<std::size_t>(node) * dim;
    return {x[0], x[1], dim == 3 ? x[2] : 0.0};
}

/// A rigid motion x -> R x + t.
struct Rigid {
    M3 r = M3::Identity();
    V3 t = V3::Zero();
    V3 operator()(const V3& x) const { return r * x + t; }
};

/// The proper rigid motion taking `from` nearest to `to` (least squares,
/// Kabsch). In 2D each point also counts once lifted by 1 along z, so the
/// rotation is about z. None when the points do not fix one (fewer than
/// three, or all on a line in 3D).
std::optional<Rigid> fit_rigid(const std::vector<V3>& from, const std::vector<V3>& to, int dim) {
    assert(from.size() == to.size());
    std::vector<V3> a = from, b = to;
    if (dim == 2)
        for (std::size_t i = 0; i < from.size(); ++i) {
            a.push_back(from[i] + V3::UnitZ());
            b.push_back(to[i] + V3::UnitZ());
        }
    if (a.size() < 3) return std::nullopt;
    V3 ca = V3::Zero(), cb = V3::Zero();
    for (std::size_t i = 0; i < a.size(); ++i) {
        ca += a[i];
        cb += b[i];
    }
    ca /= static_cast<double>(a.size());
    cb /= static_cast<double>(b.size());
    M3 h = M3::Zero();
    for (std::size_t i = 0; i < a.size(); ++i) h += (a[i] - ca) * (b[i] - cb).transpose();
    const Eigen::JacobiSVD<M3> svd(h, Eigen::ComputeFullU | Eigen::ComputeFullV);
    const V3 s = svd.singularValues();
    // Two directions with spread fix the rotation (the third by orientation).
    if (!(s[1] > 1e-12 * std::max(s[0], std::numeric_limits<double>::min()))) return std::nullopt;
    M3 d = M3::Identity();
    d(2, 2) = (svd.matrixV() * svd.matrixU().transpose()).determinant() < 0 ? -1.0 : 1.0;
    Rigid out;
    out.r = svd.matrixV() * d * svd.matrixU().transpose();
    out.t = cb - out.r * ca;
    return out;
}

/// The shortest edge of the elements of markers a and b (consecutive nodes of each element).
double shortest_edge(const Mesh& mesh, std::size_t a, std::size_t b) {
    double shortest = std::numeric_limits<double>::infinity();
    for (const std::size_t m : {a, b}) {
        const ElementList& e = mesh.markers[m].elements;
        for (std::size_t f = 0; f < e.size(); ++f) {
            const auto nodes = e.nodes_of(f);
            const std::size_t edges = nodes.size() == 2 ? 1 : nodes.size();
            for (std::size_t i = 0; i < edges; ++i) {
                const double l = (point3(mesh, nodes[i]) - point3(mesh, nodes[(i + 1) % nodes.size()])).norm();
                if (l > 0) shortest = std::min(shortest, l);
            }
        }
    }
    return shortest;
}

V3 centre(const Mesh& mesh, std::span<const NodeId> nodes) {
    V3 c = V3::Zero();
    for (const NodeId n : nodes) c += point3(mesh, n);
    return c / static_cast<double>(nodes.size());
}

/// (node of a, its image on b) for every node of a, when the elements pair
/// by order; none when they do not.
std::optional<std::vector<std::pair<NodeId, NodeId>>> pair_by_faces(const Mesh& mesh, const ElementList& a,
                                                                    const ElementList& b, double tol) {
    if (a.size() != b.size() || a.size() == 0) return std::nullopt;
    std::vector<V3> ca, cb;
    for (std::size_t f = 0; f < a.size(); ++f) {
        if (a.nodes_of(f).size() != b.nodes_of(f).size()) return std::nullopt;
        ca.push_back(centre(mesh, a.nodes_of(f)));
        cb.push_back(centre(mesh, b.nodes_of(f)));
    }
    const std::optional<Rigid> fit = fit_rigid(ca, cb, mesh.dim);
    if (!fit) return std::nullopt;
    std::vector<std::pair<NodeId, NodeId>> pairs;
    for (std::size_t f = 0; f < a.size(); ++f) {
        const auto fa = a.nodes_of(f), fb = b.nodes_of(f);
        for (const NodeId n : fa) {
            const V3 y = (*fit)(point3(mesh, n));
            double best = std::numeric_limits<double>::infinity();
            NodeId image = -1;
            for (const NodeId m : fb)
                if (const double d = (point3(mesh, m) - y).norm(); d < best) {
                    best = d;
                    image = m;
                }
            if (!(best <= tol)) return std::nullopt;
            pairs.emplace_back(n, image);
        }
    }
    return pairs;
}

/// (node of a, its image on b) under the translation between their
/// centroids, nearest node by nearest node; throws naming the first node of
/// `a` with no node of `b` within `tol` of its image.
std::vector<std::pair<NodeId, NodeId>> pair_by_translation(const Mesh& mesh, std::size_t ma, std::size_t mb,
                                                           double tol) {
    const std::vector<NodeId> a = marker_nodes(mesh.markers[ma]), b = marker_nodes(mesh.markers[mb]);
    const V3 shift = centre(mesh, b) - centre(mesh, a);
    const NearestNode tree(mesh.dim, mesh.points, b);
    std::vector<std::pair<NodeId, NodeId>> pairs;
    for (const NodeId n : a) {
        const V3 y = point3(mesh, n) + shift;
        const NearestNode::Found found = tree.nearest(y.data());
        if (!(found.distance <= tol))
            throw MeshError("cyclic markers '" + mesh.markers[ma].name + "' and '" + mesh.markers[mb].name +
                                "' are not images of each other: their faces do not pair in order, and node " +
                                std::to_string(n) + " of '" + mesh.markers[ma].name +
                                "' moved by the translation between their centroids is " +
                                std::to_string(found.distance) + " from the nearest node of '" +
                                mesh.markers[mb].name + "' (at most " + std::to_string(tol) +
                                ", a tenth of their shortest edge, makes a pair)",
                            mesh.markers[ma].name, n);
        pairs.emplace_back(n, b[static_cast<std::size_t>(found.index)]);
    }
    return pairs;
}

Rotation to_array(const M3& r) {
    Rotation out{};
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) out[static_cast<std::size_t>(3 * i + j)] = r(i, j);
    return out;
}

M3 to_matrix(const Rotation& r) {
    M3 out;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) out(i, j) = r[static_cast<std::size_t>(3 * i + j)];
    return out;
}

V3 vector3(std::span<const double> v, std::size_t member) { return {v[3 * member], v[3 * member + 1], v[3 * member + 2]}; }

}  // namespace

CyclicGroups cyclic_groups(const Mesh& mesh, std::span<const CyclicPair> pairs) {
    // Edges between a node and its image: (from, to, rotation from -> to).
    struct Edge {
        NodeId to;
        M3 r;
    };
    std::map<NodeId, std::vector<Edge>> edges;
    for (const CyclicPair& p : pairs) {
        const Marker& ma = mesh.markers[p.first];
        const Marker& mb = mesh.markers[p.second];
        const std::string names = "cyclic markers '" + ma.name + "' and '" + mb.name + "'";
        const std::vector<NodeId> a = marker_nodes(ma), b = marker_nodes(mb);
        if (a.size() != b.size())
            throw MeshError(names + " are not images of each other: they have " + std::to_string(a.size()) + " and " +
                                std::to_string(b.size()) + " nodes",
                            ma.name);
        if (a.empty()) continue;
        const double tol = 0.1 * shortest_edge(mesh, p.first, p.second);
        std::vector<std::pair<NodeId, NodeId>> found;
        if (auto by_faces = pair_by_faces(mesh, ma.elements, mb.elements, tol)) found = std::move(*by_faces);
        else found = pair_by_translation(mesh, p.first, p.second, tol);
        // One image per node, each node of b the image of one node of a.
        std::map<NodeId, NodeId> image, preimage;
        for (const auto& [n, m] : found) {
            const auto [it, fresh] = image.emplace(n, m);
            const auto [jt, fresh_b] = preimage.emplace(m, n);
            if ((!fresh && it->second != m) || (!fresh_b && jt->second != n))
                throw MeshError(names + " are not images of each other: node " +
                                    std::to_string(fresh ? jt->second : n) + " has two images (nodes " +
                                    std::to_string(fresh ? m : it->second) + " and " + std::to_string(fresh ? n : m) +
                                    ")",
                                ma.name, fresh ? jt->second : n);
        }
        if (image.size() != a.size() || preimage.size() != b.size())
            throw MeshError(names + " are not images of each other: " + std::to_string(a.size() - image.size()) +
                                " of the nodes of '" + ma.name + "' have no image",
                            ma.name);
        // One rigid motion for every node.
        std::vector<V3> from, to;
        for (const auto& [n, m] : image) {
            from.push_back(point3(mesh, n));
            to.push_back(point3(mesh, m));
        }
        const std::optional<Rigid> fit = fit_rigid(from, to, mesh.dim);
        Rigid motion;
        if (fit) motion = *fit;
        else motion.t = to.front() - from.front();  // one node, or all on a line: a translation
        for (std::size_t i = 0; i < from.size(); ++i) {
            const double off = (motion(from[i]) - to[i]).norm();
            if (off > tol) {
                const NodeId n = std::next(image.begin(), static_cast<std::ptrdiff_t>(i))->first;
                throw MeshError(names + " are not images of each other by one rigid motion: node " + std::to_string(n) +
                                    " is " + std::to_string(off) + " from where the best one takes it (at most " +
                                    std::to_string(tol) + ", a tenth of their shortest edge)",
                                ma.name, n);
            }
        }
        for (const auto& [n, m] : image) {
            edges[n].push_back({m, motion.r});
            edges[m].push_back({n, motion.r.transpose()});
        }
    }

    // Groups: breadth first from each smallest node not yet grouped.
    CyclicGroups g;
    std::map<NodeId, bool> grouped;
    for (const auto& [start, ignored] : edges) {
        if (grouped[start]) continue;
        std::deque<std::pair<NodeId, M3>> queue{{start, M3::Identity()}};
        std::vector<std::pair<NodeId, M3>> members;
        grouped[start] = true;
        while (!queue.empty()) {
            const auto [node, r] = queue.front();
            queue.pop_front();
            members.emplace_back(node, r);
            for (const Edge& e : edges[node])
                if (!grouped[e.to]) {
                    grouped[e.to] = true;
                    queue.emplace_back(e.to, e.r * r);
                }
        }
        std::sort(members.begin() + 1, members.end(), [](const auto& x, const auto& y) { return x.first < y.first; });
        for (const auto& [node, r] : members) {
            g.nodes.push_back(node);
            g.rotations.push_back(to_array(r));
        }
        g.offsets.push_back(static_cast<std::int64_t>(g.nodes.size()));
    }
    return g;
}

void couple_cyclic_vectors(const CyclicGroups& groups, std::span<double> vectors, std::span<const char> held) {
    assert(vectors.size() == 3 * groups.nodes.size() && held.size() == groups.nodes.size());
    for (std::size_t k = 0; k < groups.size(); ++k) {
        const auto begin = static_cast<std::size_t>(groups.offsets[k]), end = static_cast<std::size_t>(groups.offsets[k + 1]);
        V3 v = V3::Zero();
        std::size_t count = 0;
        for (std::size_t m = begin; m < end; ++m)
            if (held[m]) {
                v = to_matrix(groups.rotations[m]).transpose() * vector3(vectors, m);
                count = 1;
                break;
            }
        if (count == 0) {
            for (std::size_t m = begin; m < end; ++m) v += to_matrix(groups.rotations[m]).transpose() * vector3(vectors, m);
            v /= static_cast<double>(end - begin);
        }
        for (std::size_t m = begin; m < end; ++m) {
            if (held[m]) continue;
            const V3 out = to_matrix(groups.rotations[m]) * v;
            for (int d = 0; d < 3; ++d) vectors[3 * m + static_cast<std::size_t>(d)] = out[d];
        }
    }
}

CyclicVectors held_cyclic_displacements(const CyclicGroups& groups, int dim, const BoundaryMotion& motion) {
    const auto d = static_cast<std::size_t>(dim);
    CyclicVectors out{std::vector<double>(3 * groups.nodes.size(), 0.0), std::vector<char>(groups.nodes.size(), 0)};
    for (std::size_t m = 0; m < groups.nodes.size(); ++m) {
        out.held[m] = groups.slide[m] < 0;
        if (!out.held[m]) continue;
        const std::span<const double> x(groups.origins.data() + 3 * m, d);
        double y[3] = {0, 0, 0};
        apply_motion(motion[static_cast<std::size_t>(groups.slots[m])], x, {y, d});
        for (std::size_t k = 0; k < d; ++k) out.vectors[3 * m + k] = y[k] - x[k];
    }
    return out;
}

std::int64_t cyclic_disagreements(const CyclicGroups& groups, std::span<const double> vectors,
                                  std::span<const char> held, double tolerance, NodeId* node) {
    std::int64_t count = 0;
    for (std::size_t k = 0; k < groups.size(); ++k) {
        std::optional<V3> first;
        for (auto m = static_cast<std::size_t>(groups.offsets[k]); m < static_cast<std::size_t>(groups.offsets[k + 1]); ++m) {
            if (!held[m]) continue;
            const V3 v = to_matrix(groups.rotations[m]).transpose() * vector3(vectors, m);
            if (!first) {
                first = v;
            } else if ((v - *first).norm() > tolerance) {
                if (count == 0 && node) *node = groups.nodes[m];
                ++count;
                break;
            }
        }
    }
    return count;
}

}  // namespace dgwarp
