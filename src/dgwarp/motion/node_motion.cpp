#include "dgwarp/motion/node_motion.hpp"

#include <cassert>
#include <cmath>
#include <sstream>
#include <utility>

namespace dgwarp {

std::string motion_value_problem(const NodeMotion& motion) {
    const auto usable = [](const Vec3& v) {
        for (double x : v)
            if (!(std::fabs(x) <= max_motion_value)) return false;  // also false for NaN
        return true;
    };
    const std::pair<const char*, const Vec3*> parts[] = {
        {"translation", &motion.translation}, {"rotation vector", &motion.rotation}, {"centre", &motion.center}};
    for (const auto& [name, v] : parts) {
        if (usable(*v)) continue;
        std::ostringstream e;
        e << "its " << name << " (" << (*v)[0] << ", " << (*v)[1] << ", " << (*v)[2] << ") is ";
        if (std::isfinite((*v)[0]) && std::isfinite((*v)[1]) && std::isfinite((*v)[2]))
            e << "beyond " << max_motion_value << " in magnitude, more than the methods' double arithmetic holds";
        else
            e << "not finite";
        return e.str();
    }
    return {};
}

std::array<double, 9> rotation_matrix(const Vec3& w) {
    const double theta = std::sqrt(w[0] * w[0] + w[1] * w[1] + w[2] * w[2]);
    if (theta == 0.0) return {1, 0, 0, 0, 1, 0, 0, 0, 1};
    const double kx = w[0] / theta, ky = w[1] / theta, kz = w[2] / theta;
    const double c = std::cos(theta), s = std::sin(theta), v = 1.0 - c;
    return {c + kx * kx * v,      kx * ky * v - kz * s, kx * kz * v + ky * s,
            ky * kx * v + kz * s, c + ky * ky * v,      ky * kz * v - kx * s,
            kz * kx * v - ky * s, kz * ky * v + kx * s, c + kz * kz * v};
}

void apply_motion(const NodeMotion& motion, std::span<const double> x, std::span<double> out) {
    const std::size_t dim = x.size();
    assert(dim == 2 || dim == 3);
    assert(out.size() >= dim);
    if (dim == 2) {
        const double a = motion.rotation[2];
        const double c = std::cos(a), s = std::sin(a);
        const double dx = x[0] - motion.center[0], dy = x[1] - motion.center[1];
        out[0] = motion.center[0] + c * dx - s * dy + motion.translation[0];
        out[1] = motion.center[1] + s * dx + c * dy + motion.translation[1];
        return;
    }
    const auto r = rotation_matrix(motion.rotation);
    const double d[3] = {x[0] - motion.center[0], x[1] - motion.center[1], x[2] - motion.center[2]};
    for (int i = 0; i < 3; ++i)
        out[i] = motion.center[i] + r[3 * i] * d[0] + r[3 * i + 1] * d[1] + r[3 * i + 2] * d[2] +
                 motion.translation[i];
}

}  // namespace dgwarp
