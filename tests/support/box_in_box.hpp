#pragma once
// A structured box-in-box point set for deformation tests: the nodes of a
// grid on [0, size]^dim without the inside of an inner box. Nodes on the outer
// box are static boundary nodes, nodes on the inner box moving ones. No cells:
// the methods under test only need points and a boundary set.
#include <algorithm>
#include <random>
#include <span>
#include <vector>

#include "dgwarp/motion/node_motion.hpp"

namespace dgwarp::test {

struct BoxInBox {
    int dim = 2;
    std::vector<double> points;  // num_points × dim
    BoundarySet boundary;        // outer box static, inner box moving
    std::vector<NodeId> volume;  // the other nodes, ascending
    Vec3 inner_center{};         // centre of the inner box

    std::size_t num_points() const { return points.size() / static_cast<std::size_t>(dim); }
};

/// n + 1 grid nodes per side (n >= 4); the inner box spans grid indices
/// [n/3, n - n/3]. `size` scales all coordinates.
inline BoxInBox box_in_box(int dim, int n, double size = 1.0) {
    BoxInBox m;
    m.dim = dim;
    const int lo = n / 3, hi = n - n / 3;
    const int nz = dim == 3 ? n : 0;
    NodeId id = 0;
    for (int k = 0; k <= nz; ++k)
        for (int j = 0; j <= n; ++j)
            for (int i = 0; i <= n; ++i) {
                const int c[3] = {i, j, k};
                bool inside = true, on_inner = true, on_outer = false;
                for (int d = 0; d < dim; ++d) {
                    inside &= c[d] > lo && c[d] < hi;
                    on_inner &= c[d] >= lo && c[d] <= hi;
                    on_outer |= c[d] == 0 || c[d] == n;
                }
                if (inside) continue;
                on_inner &= !inside;
                for (int d = 0; d < dim; ++d) m.points.push_back(size * c[d] / n);
                if (on_outer || on_inner) {
                    m.boundary.nodes.push_back(id);
                    m.boundary.moving.push_back(on_inner ? 1 : 0);
                } else {
                    m.volume.push_back(id);
                }
                ++id;
            }
    for (int d = 0; d < dim; ++d) m.inner_center[d] = size * 0.5 * (lo + hi) / n;
    return m;
}

/// `m` with every coordinate moved by up to ±amount (uniform, from `seed`):
/// removes the cospherical point sets of a grid, whose Delaunay graph is not unique.
inline BoxInBox jittered(BoxInBox m, double amount, unsigned seed) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> u(-amount, amount);
    for (double& x : m.points) x += u(rng);
    return m;
}

/// `m` with every boundary node moving, the outer box's too.
inline BoxInBox all_moving(BoxInBox m) {
    std::fill(m.boundary.moving.begin(), m.boundary.moving.end(), std::uint8_t{1});
    return m;
}

/// Where node `node` of `points` (num_points × dim) goes under `m` (apply_motion).
inline std::vector<double> moved(int dim, const std::vector<double>& points, std::size_t node, const NodeMotion& m) {
    std::vector<double> y(static_cast<std::size_t>(dim));
    apply_motion(m, std::span<const double>(points.data() + node * dim, dim), y);
    return y;
}

/// A per-node motion of the moving nodes of `m` (translation, rotation and
/// centre all varying by up to ±amount, rotations by ±4·amount), zero for the
/// static ones; deterministic for a seed.
inline BoundaryMotion random_motion(const BoxInBox& m, std::uint32_t seed, double amount = 0.05) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> u(-amount, amount);
    BoundaryMotion motion(m.boundary.nodes.size());
    for (std::size_t b = 0; b < motion.size(); ++b) {
        if (!m.boundary.moving[b]) continue;
        for (int d = 0; d < 3; ++d) {
            motion[b].translation[d] = u(rng);
            motion[b].rotation[d] = m.dim == 3 || d == 2 ? 4 * u(rng) : 0;
            motion[b].center[d] = m.dim == 3 || d < 2 ? m.inner_center[d] + u(rng) : 0;
        }
    }
    return motion;
}

}  // namespace dgwarp::test
