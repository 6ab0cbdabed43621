#include "dgwarp/picture/picture_window.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "dgwarp/core/error.hpp"

namespace dgwarp {

std::array<double, 4> enlarge_to_aspect(const std::array<double, 4>& window, double aspect) {
    const double cx = 0.5 * (window[0] + window[1]), cy = 0.5 * (window[2] + window[3]);
    double half_w = 0.5 * (window[1] - window[0]), half_h = 0.5 * (window[3] - window[2]);
    if (half_w < aspect * half_h)
        half_w = aspect * half_h;
    else
        half_h = half_w / aspect;
    return {cx - half_w, cx + half_w, cy - half_h, cy + half_h};
}

std::array<double, 4> window_around(const Mesh& mesh, std::span<const NodeId> nodes, double margin_factor,
                                    double aspect) {
    if (!(std::isfinite(margin_factor) && margin_factor > 0))
        throw Error("picture window: margin factor must be finite and positive, got " +
                    std::to_string(margin_factor));
    if (!(std::isfinite(aspect) && aspect > 0))
        throw Error("picture window: aspect ratio must be finite and positive, got " + std::to_string(aspect));
    if (nodes.empty()) throw MeshError("picture window: no nodes to frame");
    if (mesh.dim != 2 && mesh.dim != 3) throw MeshError("picture window: mesh dimension must be 2 or 3");
    constexpr double inf = std::numeric_limits<double>::infinity();
    std::array<double, 4> box = {inf, -inf, inf, -inf};
    const auto num_points = static_cast<std::int64_t>(mesh.num_points());
    for (std::size_t k = 0; k < nodes.size(); ++k) {
        const NodeId n = nodes[k];
        if (n < 0 || n >= num_points)
            throw MeshError("picture window: node id " + std::to_string(n) + " is out of range (mesh has " +
                                std::to_string(num_points) + " nodes)",
                            {}, static_cast<std::int64_t>(k));
        const double x = mesh.points[static_cast<std::size_t>(n) * mesh.dim];
        const double y = mesh.points[static_cast<std::size_t>(n) * mesh.dim + 1];
        box = {std::min(box[0], x), std::max(box[1], x), std::min(box[2], y), std::max(box[3], y)};
    }
    double half_w = 0.5 * (box[1] - box[0]), half_h = 0.5 * (box[3] - box[2]);
    if (half_w == 0 && half_h == 0) {
        const BoundingBox b = bounding_box(mesh);
        half_w = 0.005 * std::hypot(b.max[0] - b.min[0], b.max[1] - b.min[1]);
        if (half_w == 0) half_w = 0.5;  // a mesh of one point: any size will do
    }
    const double cx = 0.5 * (box[0] + box[1]), cy = 0.5 * (box[2] + box[3]);
    half_w *= margin_factor;
    half_h *= margin_factor;
    return enlarge_to_aspect({cx - half_w, cx + half_w, cy - half_h, cy + half_h}, aspect);
}

}  // namespace dgwarp
