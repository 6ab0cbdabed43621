#include "dgwarp/mesh/polyhedron_faces.hpp"

#include <algorithm>
#include <array>
#include <cstdint>
#include <vector>

namespace dgwarp {

namespace {

struct Edge {
    NodeId low, high;  // its nodes, sorted
    std::size_t face;
    bool forward;  // the face runs it low -> high
};

}  // namespace

std::optional<std::string> orient_polyhedron_faces(std::span<NodeId> rings, std::span<const int> face_sizes,
                                                   std::span<const double> points) {
    const std::size_t nf = face_sizes.size();
    std::vector<std::size_t> start(nf + 1, 0);
    for (std::size_t f = 0; f < nf; ++f) start[f + 1] = start[f] + static_cast<std::size_t>(face_sizes[f]);
    std::vector<Edge> edges;
    for (std::size_t f = 0; f < nf; ++f)
        for (std::size_t k = start[f]; k < start[f + 1]; ++k) {
            const NodeId a = rings[k], b = rings[k + 1 < start[f + 1] ? k + 1 : start[f]];
            edges.push_back({std::min(a, b), std::max(a, b), f, a < b});
        }
    std::sort(edges.begin(), edges.end(), [](const Edge& x, const Edge& y) {
        return x.low != y.low ? x.low < y.low : x.high != y.high ? x.high < y.high : x.face < y.face;
    });
    // Each edge in two faces: its partner per (face, edge).
    std::vector<std::vector<std::pair<std::size_t, bool>>> next(nf);  // (other face, whether they agree now)
    for (std::size_t i = 0; i < edges.size();) {
        std::size_t j = i;
        while (j < edges.size() && edges[j].low == edges[i].low && edges[j].high == edges[i].high) ++j;
        if (j - i != 2)
            return "the edge " + std::to_string(edges[i].low) + "-" + std::to_string(edges[i].high) + " is in " +
                   std::to_string(j - i) + " of its faces, not 2";
        const Edge &x = edges[i], &y = edges[i + 1];
        const bool consistent = x.forward != y.forward;
        next[x.face].push_back({y.face, consistent});
        next[y.face].push_back({x.face, consistent});
        i = j;
    }
    // Flip faces from the first outwards so that each agrees with its neighbours.
    std::vector<std::int8_t> flip(nf, -1);
    std::vector<std::size_t> todo{0};
    if (nf > 0) flip[0] = 0;
    while (!todo.empty()) {
        const std::size_t f = todo.back();
        todo.pop_back();
        for (const auto& [g, consistent] : next[f]) {
            const std::int8_t want = static_cast<std::int8_t>(consistent ? flip[f] : 1 - flip[f]);
            if (flip[g] < 0) {
                flip[g] = want;
                todo.push_back(g);
            } else if (flip[g] != want) {
                return std::string("its faces cannot all be turned one way (a one-sided surface)");
            }
        }
    }
    for (std::size_t f = 0; f < nf; ++f)
        if (flip[f] < 0) return std::string("its faces are not connected by their edges");
    const auto turn = [&](std::size_t f) { std::reverse(rings.begin() + static_cast<std::ptrdiff_t>(start[f]) + 1,
                                                        rings.begin() + static_cast<std::ptrdiff_t>(start[f + 1])); };
    for (std::size_t f = 0; f < nf; ++f)
        if (flip[f] == 1) turn(f);
    // Outward: the volume the faces enclose positive. Summed so that turning
    // every face gives exactly its negative (the centres over the nodes in id
    // order, each face's edges in the order of their nodes), so that faces
    // read back after turning stay as they are, even for a flat polyhedron.
    using P = std::array<double, 3>;
    const auto at = [&](NodeId n) {
        const double* x = points.data() + static_cast<std::size_t>(n) * 3;
        return P{x[0], x[1], x[2]};
    };
    const auto centre = [&](std::vector<NodeId> ids) {
        std::sort(ids.begin(), ids.end());
        ids.erase(std::unique(ids.begin(), ids.end()), ids.end());
        P m{0, 0, 0};
        for (NodeId n : ids)
            for (int d = 0; d < 3; ++d) m[d] += at(n)[d];
        for (double& v : m) v /= static_cast<double>(ids.size());
        return m;
    };
    const P c = centre({rings.begin(), rings.end()});
    double volume = 0;
    std::vector<Edge> face_edges;
    for (std::size_t f = 0; f < nf; ++f) {
        const P fc = centre({rings.begin() + static_cast<std::ptrdiff_t>(start[f]), rings.begin() + static_cast<std::ptrdiff_t>(start[f + 1])});
        face_edges.clear();
        for (std::size_t k = start[f]; k < start[f + 1]; ++k) {
            const NodeId a = rings[k], b = rings[k + 1 < start[f + 1] ? k + 1 : start[f]];
            face_edges.push_back({std::min(a, b), std::max(a, b), f, a < b});
        }
        std::sort(face_edges.begin(), face_edges.end(),
                  [](const Edge& x, const Edge& y) { return x.low != y.low ? x.low < y.low : x.high < y.high; });
        double sum = 0;
        for (const Edge& e : face_edges) {
            const P a = at(e.low), b = at(e.high);
            const P u{a[0] - c[0], a[1] - c[1], a[2] - c[2]}, v{b[0] - c[0], b[1] - c[1], b[2] - c[2]};
            const P n{u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
            const double t = n[0] * (fc[0] - c[0]) + n[1] * (fc[1] - c[1]) + n[2] * (fc[2] - c[2]);
            sum += e.forward ? t : -t;
        }
        volume += sum;
    }
    if (volume < 0)
        for (std::size_t f = 0; f < nf; ++f) turn(f);
    return std::nullopt;
}

}  // namespace dgwarp
