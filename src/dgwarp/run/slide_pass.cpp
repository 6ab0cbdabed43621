#include "dgwarp/run/slide_pass.hpp"

#include <cassert>

#include "dgwarp/motion/slide_planes.hpp"

namespace dgwarp {

SlidePass prepare_slide_pass(Method method, const Mesh& mesh, const ResolvedBoundary& resolved,
                             const MethodOptions& options) {
    SlidePass pass;
    pass.method = method == Method::laplacian ? Method::dg_harmonic : method;
    pass.options = options;
    pass.dim = mesh.dim;
    pass.slides = resolved.slides;
    const auto dim = static_cast<std::size_t>(mesh.dim);
    const BoundarySet& b = resolved.boundary;
    // The other boundary nodes: every boundary node but the sliding ones (slots ascending, as the nodes).
    std::size_t next = 0;
    for (std::size_t i = 0; i < b.nodes.size(); ++i) {
        if (next < pass.slides.slots.size() && static_cast<std::size_t>(pass.slides.slots[next]) == i) {
            ++next;
            continue;
        }
        pass.source_slots.push_back(static_cast<std::int32_t>(i));
        pass.boundary.nodes.push_back(static_cast<NodeId>(pass.boundary.nodes.size()));
        pass.boundary.moving.push_back(b.moving[i]);
        const double* x = mesh.points.data() + static_cast<std::size_t>(b.nodes[i]) * dim;
        pass.points.insert(pass.points.end(), x, x + dim);
    }
    pass.points.insert(pass.points.end(), pass.slides.origins.begin(), pass.slides.origins.end());
    pass.plan = prepare(pass.method, mesh.dim, pass.points, pass.boundary, pass.options);
    return pass;
}

void slide_motion(const SlidePass& pass, BoundaryMotion& motion) {
    BoundaryMotion sources(pass.source_slots.size());
    for (std::size_t i = 0; i < sources.size(); ++i) sources[i] = motion[static_cast<std::size_t>(pass.source_slots[i])];
    std::vector<double> moved(pass.points.size());
    deform(pass.plan, pass.points, sources, moved, pass.options);
    const auto dim = static_cast<std::size_t>(pass.dim);
    const std::size_t first = pass.source_slots.size() * dim;
    std::vector<double> displacement(moved.size() - first);
    for (std::size_t k = 0; k < displacement.size(); ++k) displacement[k] = moved[first + k] - pass.points[first + k];
    project_slide_vectors(pass.slides, pass.dim, displacement);
    for (std::size_t i = 0; i < pass.slides.size(); ++i) {
        NodeMotion m;
        for (std::size_t k = 0; k < dim; ++k) m.translation[k] = displacement[i * dim + k];
        motion[static_cast<std::size_t>(pass.slides.slots[i])] = m;
    }
}

}  // namespace dgwarp
