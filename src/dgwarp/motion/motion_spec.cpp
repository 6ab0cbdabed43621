#include "dgwarp/motion/motion_spec.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <numbers>

namespace dgwarp {

Vec3 rotation_vector(double angle, const Vec3& axis) {
    // Scaled by a power of two first (exact: the same bits as unscaled), so
    // that the squares neither underflow (an axis [0, 0, 1e-300]) nor overflow.
    const double largest = std::max({std::abs(axis[0]), std::abs(axis[1]), std::abs(axis[2])});
    assert(largest > 0 && std::isfinite(largest));
    const int e = std::ilogb(largest);
    const Vec3 a{std::ldexp(axis[0], -e), std::ldexp(axis[1], -e), std::ldexp(axis[2], -e)};
    const double norm = std::sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]);
    return {angle * a[0] / norm, angle * a[1] / norm, angle * a[2] / norm};
}

NodeMotion periodic_motion_at(const PeriodicMotion& motion, double t) {
    NodeMotion m;
    if (motion.pitch) {
        const Pitch& p = *motion.pitch;
        const double angle = p.mean + p.amplitude * std::sin(2 * std::numbers::pi * p.frequency * t + p.phase);
        m.rotation = rotation_vector(angle, p.axis);
        m.center = p.center;
    }
    if (motion.plunge) {
        const Plunge& p = *motion.plunge;
        const double s = std::sin(2 * std::numbers::pi * p.frequency * t + p.phase);
        m.translation = {p.amplitude[0] * s, p.amplitude[1] * s, p.amplitude[2] * s};
    }
    return m;
}

std::size_t frame_count(const MotionSpec& spec) {
    return spec.time ? static_cast<std::size_t>(spec.time->steps) : spec.frames.size();
}

double frame_time(const MotionSpec& spec, std::size_t frame) {
    return spec.time ? static_cast<double>(frame) * spec.time->time_step : 0.0;
}

const MotionFrame& frame_spec(const MotionSpec& spec, std::size_t frame) {
    assert(frame < frame_count(spec));
    return spec.time ? spec.frames.at(0) : spec.frames.at(frame);
}

const MarkerMotion& marker_motion(const MotionSpec& spec, const MotionFrame& frame,
                                  const std::string& name) {
    const auto it = frame.markers.find(name);
    return it == frame.markers.end() ? spec.default_motion : it->second;
}

std::vector<std::string> slide_unless_named(MotionSpec& spec, const std::vector<std::string>& markers) {
    std::vector<std::string> made;
    if (spec.default_given || !std::holds_alternative<FixedMotion>(spec.default_motion)) return made;
    for (const std::string& name : markers) {
        const bool named = std::any_of(spec.frames.begin(), spec.frames.end(),
                                       [&](const MotionFrame& f) { return f.markers.count(name) > 0; });
        if (named) continue;
        for (MotionFrame& f : spec.frames) f.markers.emplace(name, SlideMotion{});
        made.push_back(name);
    }
    return made;
}

std::vector<std::pair<std::string, std::string>> couple_unless_named(
    MotionSpec& spec, const std::vector<std::pair<std::string, std::string>>& pairs) {
    std::vector<std::pair<std::string, std::string>> made;
    if (spec.default_given || !std::holds_alternative<FixedMotion>(spec.default_motion)) return made;
    const auto named = [&](const std::string& name) {
        return std::any_of(spec.frames.begin(), spec.frames.end(),
                           [&](const MotionFrame& f) { return f.markers.count(name) > 0; });
    };
    for (const auto& [a, b] : pairs) {
        if (named(a) || named(b)) continue;
        for (MotionFrame& f : spec.frames) {
            f.markers.emplace(a, CyclicMotion{b});
            f.markers.emplace(b, CyclicMotion{a});
        }
        made.emplace_back(a, b);
    }
    return made;
}

void rename_marker(MotionSpec& spec, const std::string& from, const std::string& to) {
    for (MotionFrame& f : spec.frames) {
        if (auto node = f.markers.extract(from)) {
            node.key() = to;
            f.markers.insert(std::move(node));
        }
        for (auto& [name, motion] : f.markers)
            if (auto* c = std::get_if<CyclicMotion>(&motion); c && c->partner == from) c->partner = to;
    }
}

const char* motion_kind_name(const MarkerMotion& motion) {
    static constexpr const char* names[] = {"fixed",        "rigid",            "periodic", "displacement_file",
                                            "surface_file", "node_motion_file", "slide",     "cyclic"};
    static_assert(std::variant_size_v<MarkerMotion> == std::size(names));
    return names[motion.index()];
}

}  // namespace dgwarp
