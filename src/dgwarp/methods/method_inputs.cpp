#include "dgwarp/methods/method_inputs.hpp"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <sstream>
#include <string>

#include "dgwarp/core/error.hpp"
#include "dgwarp/core/parallel_for.hpp"
#include "dgwarp/methods/boundary_set_tools.hpp"

namespace dgwarp {

std::size_t check_points_and_boundary(std::string_view method, int dim, std::span<const double> points,
                                      const BoundarySet& boundary) {
    const std::size_t num_points = checked_point_count(method, dim, points);
    check_boundary_set(num_points, boundary);
    return num_points;
}

std::vector<NodeId> split_volume_nodes(std::size_t num_points, const BoundarySet& boundary,
                                       std::vector<std::int32_t>& node_simplex) {
    std::vector<NodeId> volume;
    volume.reserve(num_points - std::min(num_points, boundary.nodes.size()));
    node_simplex.assign(num_points, 0);
    for (std::size_t n = 0, b = 0; n < num_points; ++n) {
        if (b < boundary.nodes.size() && static_cast<std::size_t>(boundary.nodes[b]) == n) {
            node_simplex[n] = -1 - static_cast<std::int32_t>(b++);
        } else {
            volume.push_back(static_cast<NodeId>(n));
        }
    }
    return volume;
}

void check_step_arrays(std::string_view method, std::int64_t num_points, int dim,
                       std::span<const NodeId> boundary_nodes, std::span<const double> points,
                       const BoundaryMotion& motion, std::span<const double> out) {
    const std::string name(method);
    const auto expected = static_cast<std::size_t>(num_points) * static_cast<std::size_t>(dim);
    if (points.size() != expected)
        throw MeshError(name + ": the plan is for " + std::to_string(num_points) + " points (" +
                        std::to_string(expected) + " coordinates), got " + std::to_string(points.size()) +
                        " coordinates");
    if (out.size() != expected)
        throw MeshError(name + ": the output array holds " + std::to_string(out.size()) + " values, expected " +
                        std::to_string(expected) + " (" + std::to_string(num_points) + " points)");
    if (motion.size() != boundary_nodes.size())
        throw MeshError(name + ": the motion has " + std::to_string(motion.size()) + " entries but the plan has " +
                        std::to_string(boundary_nodes.size()) + " boundary nodes");
    for (std::size_t b = 0; b < motion.size(); ++b)
        if (const std::string problem = motion_value_problem(motion[b]); !problem.empty())
            throw MeshError(name + ": the motion of boundary node " + std::to_string(boundary_nodes[b]) +
                                " (boundary index " + std::to_string(b) + ") cannot be used: " + problem,
                            {}, boundary_nodes[b]);
}

namespace {
// Whether a value of `v` is NaN or infinite: a test of the exponent bits,
// which the compiler vectorises (a step's result is scanned every step).
bool any_non_finite(std::span<const double> v) {
    constexpr std::uint64_t exponent = 0x7ff0000000000000ULL;
    std::atomic<bool> found{false};
    parallel_for_chunks(static_cast<std::int64_t>(v.size()), [&](std::int64_t begin, std::int64_t end) {
        std::uint64_t bad = 0;
        for (std::int64_t i = begin; i < end; ++i) {
            std::uint64_t bits;
            std::memcpy(&bits, &v[static_cast<std::size_t>(i)], sizeof bits);
            bad |= static_cast<std::uint64_t>((bits & exponent) == exponent);
        }
        if (bad) found.store(true, std::memory_order_relaxed);
    });
    return found.load();
}
}  // namespace

std::string non_finite_result(std::string_view method, int dim, std::span<const double> out,
                              const BoundaryMotion& motion, std::int64_t& count) {
    const auto d = static_cast<std::size_t>(dim);
    count = 0;
    if (!any_non_finite(out)) return {};
    std::size_t first = 0;
    for (std::size_t n = 0; n < out.size() / d; ++n) {
        bool finite = true;
        for (std::size_t i = 0; i < d; ++i) finite = finite && std::isfinite(out[n * d + i]);
        if (!finite && count++ == 0) first = n;
    }
    if (count == 0) return {};
    // Largest magnitudes, componentwise (no squares: they would overflow themselves).
    const auto largest = [&](Vec3 NodeMotion::*v) {
        double m = 0;
        for (const NodeMotion& nm : motion)
            for (double x : nm.*v) m = std::max(m, std::abs(x));
        return m;
    };
    const double t = largest(&NodeMotion::translation), w = largest(&NodeMotion::rotation),
                 c = largest(&NodeMotion::center);
    std::ostringstream e;
    e.precision(6);
    e << method << ": node " << first << " has a non-finite new coordinate (";
    for (std::size_t i = 0; i < d; ++i) e << (i ? ", " : "") << out[first * d + i];
    e << ")";
    if (count > 1) e << ", and " << count - 1 << " other node" << (count > 2 ? "s" : "") << " too";
    e << ": the arithmetic overflowed. The motion's largest translation component is " << t
      << ", rotation component " << w << " rad, centre coordinate " << c << "; ";
    // Squares of these are summed on the way: beyond ~1e150 they overflow.
    if (std::max({t, w, c}) > 1e150)
        e << "a motion this large cannot be computed in double precision: give the motion in the mesh's units";
    else
        e << "the method's options (such as DG-IDW's a and L) make its weights overflow: use values nearer "
             "their defaults";
    return e.str();
}

void check_step_result(std::string_view method, int dim, std::span<const double> out, const BoundaryMotion& motion) {
    std::int64_t count = 0;
    if (std::string e = non_finite_result(method, dim, out, motion, count); !e.empty()) throw InvalidResultError(e, count);
}

}  // namespace dgwarp

