#pragma once
// The motion of a node, as METHODS.md defines it: a translation t, a rotation
// vector w (axis times angle, radians; in 2D only w[2] is used) and a rotation
// centre c. The node moves from x to c + R(w)(x - c) + t, R the Rodrigues
// rotation. Static nodes have t = 0, w = 0.
#include <array>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "dgwarp/mesh/mesh.hpp"

namespace dgwarp {

using Vec3 = std::array<double, 3>;

struct NodeMotion {
    Vec3 translation{};  // t
    Vec3 rotation{};     // w: axis × angle (radians)
    Vec3 center{};       // c

    bool operator==(const NodeMotion&) const = default;
};

/// The largest magnitude of a motion value (a translation, rotation vector or
/// centre component, a new coordinate) that every method computes with: the
/// methods add squares and products of these, which overflow beyond ~1e154.
inline constexpr double max_motion_value = 1e150;

/// Empty when every value of `motion` is finite and at most max_motion_value
/// in magnitude (only these can be deformed with); otherwise what is wrong,
/// e.g. "its translation (1.7e+308, 0, 0) is beyond 1e+150 in magnitude".
/// One rule for the motion files (resolve_frame, so `check` as `deform`) and
/// for motions given as arrays (each method's deform).
std::string motion_value_problem(const NodeMotion& motion);

/// The rotation matrix R(w) (Rodrigues), row-major 3×3; identity for w = 0.
std::array<double, 9> rotation_matrix(const Vec3& w);

/// The new position of a point `x` (dim 2 or 3 coordinates) under `motion`;
/// writes dim coordinates to `out`. In 2D, only rotation[2] is used.
void apply_motion(const NodeMotion& motion, std::span<const double> x, std::span<double> out);

/// The boundary of a deformation problem: the boundary nodes (sorted, unique
/// mesh node ids) and, for each, whether it moves (1) or stays (0). Fixed for
/// the life of a plan: it decides the Delaunay graph and the weights.
struct BoundarySet {
    std::vector<NodeId> nodes;
    std::vector<std::uint8_t> moving;  // same size as nodes
};

/// How many of `b`'s nodes move.
inline std::int64_t moving_count(const BoundarySet& b) {
    std::int64_t n = 0;
    for (std::uint8_t m : b.moving) n += m;
    return n;
}

/// One step's motion: one NodeMotion per boundary node, in BoundarySet order.
/// Static nodes must have zero translation and rotation.
using BoundaryMotion = std::vector<NodeMotion>;

}  // namespace dgwarp
