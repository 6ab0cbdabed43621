#pragma once
// Moving boundary nodes by their own motion inside a per-node loop.
#include <array>
#include <cmath>
#include <cstring>

#include "dgwarp/motion/node_motion.hpp"

namespace dgwarp {

// apply_motion for runs of boundary nodes that share a rotation (a rigid
// marker): the rotation matrix (3D) or cos/sin (2D) of the last rotation
// vector is reused. Same values, same expressions as apply_motion, so the
// result is bit-identical to it; only the std::sin/std::cos calls are saved.
template <int Dim>
class BoundaryMover {
public:
    void move(const NodeMotion& motion, const double* x, double* out) {
        if (std::memcmp(&motion.rotation, &rotation_, sizeof rotation_) != 0 || !valid_) {
            rotation_ = motion.rotation;
            valid_ = true;
            if constexpr (Dim == 2) {
                cos_ = std::cos(motion.rotation[2]);
                sin_ = std::sin(motion.rotation[2]);
            } else {
                r_ = rotation_matrix(motion.rotation);
            }
        }
        if constexpr (Dim == 2) {
            const double c = cos_, s = sin_;
            const double dx = x[0] - motion.center[0], dy = x[1] - motion.center[1];
            out[0] = motion.center[0] + c * dx - s * dy + motion.translation[0];
            out[1] = motion.center[1] + s * dx + c * dy + motion.translation[1];
        } else {
            const auto& r = r_;
            const double d[3] = {x[0] - motion.center[0], x[1] - motion.center[1], x[2] - motion.center[2]};
            for (int i = 0; i < 3; ++i)
                out[i] = motion.center[i] + r[3 * i] * d[0] + r[3 * i + 1] * d[1] + r[3 * i + 2] * d[2] +
                         motion.translation[i];
        }
    }

private:
    bool valid_ = false;
    Vec3 rotation_{};
    double cos_ = 1, sin_ = 0;
    std::array<double, 9> r_{};
};

}  // namespace dgwarp
