#include "dgwarp/run/slide_pass.hpp"

#include <cassert>

#include "dgwarp/motion/slide_planes.hpp"

namespace dgwarp {

namespace {

/// Each cyclic node and its images (slides.cyclic) moved alike: the free ones
/// (`displacement`, per sliding node) take what a held one's motion gives it
/// (`motion`), else their mean, through their rotations; then back in their
/// planes (a no-op where the planes are images of each other, as a 2D case's
/// front and back are under its translation).
void couple_cyclic_nodes(const SlideSet& slides, int dim, const BoundaryMotion& motion, std::vector<double>& displacement) {
    const CyclicGroups& g = slides.cyclic;
    if (g.empty()) return;
    const auto d = static_cast<std::size_t>(dim);
    auto [vectors, held] = held_cyclic_displacements(g, dim, motion);
    for (std::size_t m = 0; m < g.nodes.size(); ++m)
        if (!held[m])
            for (std::size_t k = 0; k < d; ++k)
                vectors[3 * m + k] = displacement[static_cast<std::size_t>(g.slide[m]) * d + k];
    couple_cyclic_vectors(g, vectors, held);
    for (std::size_t m = 0; m < g.nodes.size(); ++m)
        if (!held[m])
            for (std::size_t k = 0; k < d; ++k)
                displacement[static_cast<std::size_t>(g.slide[m]) * d + k] = vectors[3 * m + k];
    project_slide_vectors(slides, dim, displacement);
}

}  // namespace

Method slide_pass_method(const ResolvedBoundary& resolved) {
    const std::size_t others = resolved.boundary.nodes.size() - resolved.slides.size();
    return others <= max_slide_rbf_centres ? Method::rbf : Method::dg_harmonic;
}

SlidePass prepare_slide_pass(const Mesh& mesh, const ResolvedBoundary& resolved,
                             const MethodOptions& options) {
    SlidePass pass;
    pass.method = slide_pass_method(resolved);
    pass.options = options;
    pass.dim = mesh.dim;
    pass.slides = resolved.slides;
    // DG-harmonic's coarse level is made of the volume nodes too: its first
    // pass runs on the whole mesh. RBF moves each node from the boundary nodes
    // alone: the small problem gives the same motion, faster.
    pass.whole_mesh = pass.method == Method::dg_harmonic;
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
        pass.boundary.nodes.push_back(pass.whole_mesh ? b.nodes[i] : static_cast<NodeId>(pass.boundary.nodes.size()));
        pass.boundary.moving.push_back(b.moving[i]);
        if (pass.whole_mesh) continue;
        const double* x = mesh.points.data() + static_cast<std::size_t>(b.nodes[i]) * dim;
        pass.points.insert(pass.points.end(), x, x + dim);
    }
    if (pass.whole_mesh) pass.points = mesh.points;
    else pass.points.insert(pass.points.end(), pass.slides.origins.begin(), pass.slides.origins.end());
    pass.options.rbf = RbfOptions{};  // global support, every other boundary node a centre
    pass.plan = prepare(pass.method, mesh.dim, pass.points, pass.boundary, pass.options);
    return pass;
}

void slide_motion(const SlidePass& pass, BoundaryMotion& motion) {
    BoundaryMotion sources(pass.source_slots.size());
    for (std::size_t i = 0; i < sources.size(); ++i) sources[i] = motion[static_cast<std::size_t>(pass.source_slots[i])];
    std::vector<double> moved(pass.points.size());
    deform(pass.plan, pass.points, sources, moved, pass.options);
    const auto dim = static_cast<std::size_t>(pass.dim);
    std::vector<double> displacement(pass.slides.size() * dim);
    for (std::size_t i = 0; i < pass.slides.size(); ++i) {
        const std::size_t at =
            pass.whole_mesh ? static_cast<std::size_t>(pass.slides.nodes[i]) * dim : (pass.source_slots.size() + i) * dim;
        for (std::size_t k = 0; k < dim; ++k) displacement[i * dim + k] = moved[at + k] - pass.points[at + k];
    }
    project_slide_vectors(pass.slides, pass.dim, displacement);
    couple_cyclic_nodes(pass.slides, pass.dim, motion, displacement);
    for (std::size_t i = 0; i < pass.slides.size(); ++i) {
        NodeMotion m;
        for (std::size_t k = 0; k < dim; ++k) m.translation[k] = displacement[i * dim + k];
        motion[static_cast<std::size_t>(pass.slides.slots[i])] = m;
    }
}

}  // namespace dgwarp
