#include "dgwarp/job/boundary_displacement.hpp"

#include <algorithm>

#include "dgwarp/run/slide_pass.hpp"

namespace dgwarp {

BoundaryDisplacement boundary_displacement(const JobInputs& in, std::size_t frame) {
    ResolvedFrame resolved = resolve_frame(in.mesh, in.spec, in.boundary, frame);
    // Sliding nodes: the motion the first pass gives them (docs/MOTION.md).
    if (!in.boundary.slides.empty()) slide_motion(prepare_slide_pass(in.mesh, in.boundary), resolved.motion);
    BoundaryDisplacement d;
    d.warnings = std::move(resolved.warnings);
    d.displacement = node_displacements(in.mesh, in.boundary.boundary, resolved.motion);
    d.boundary = in.boundary.boundary;
    if (!in.planar) return d;
    // A 2D case: the 3D nodes' displacements, each its 2D node's, and both twins of each boundary node.
    std::vector<double> moved = in.mesh.points, lifted;
    for (std::size_t i = 0; i < moved.size(); ++i) moved[i] += d.displacement[i];
    const std::span<const double> points = output_points(in, moved, lifted);
    d.displacement.assign(points.begin(), points.end());
    for (std::size_t i = 0; i < d.displacement.size(); ++i) d.displacement[i] -= in.file_mesh.points[i];
    BoundarySet twins;
    const BoundarySet& b = in.boundary.boundary;
    for (std::size_t v = 0; v < in.planar->node_2d.size(); ++v) {
        const NodeId j = in.planar->node_2d[v];
        const auto it = std::lower_bound(b.nodes.begin(), b.nodes.end(), j);
        if (it == b.nodes.end() || *it != j) continue;
        twins.nodes.push_back(static_cast<NodeId>(v));
        twins.moving.push_back(b.moving[static_cast<std::size_t>(it - b.nodes.begin())]);
    }
    d.boundary = std::move(twins);
    return d;
}

}  // namespace dgwarp
