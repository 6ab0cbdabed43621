#pragma once
// The first pass of a step with sliding markers (SlideMotion, docs/MOTION.md
// "Sliding markers"). A sliding node's motion is not given: each frame, the
// method moves the sliding nodes as volume nodes of a small problem (the
// boundary nodes of the other markers, and the sliding nodes), their
// displacements are put into their planes (slide_planes.hpp), and the step
// proper then moves the mesh with the sliding nodes as moving boundary nodes
// of that motion. So the volume next to a sliding wall follows its nodes and
// does not cross it, as it would if the sliding nodes were only projected back
// after a step that ignored them (measured: thin cells at the walls of random
// 2D scenes folded that way).
#include <cstdint>
#include <vector>

#include "dgwarp/mesh/mesh.hpp"
#include "dgwarp/methods/method.hpp"
#include "dgwarp/motion/resolve_motion.hpp"

namespace dgwarp {

struct SlidePass {
    Method method = Method::dg_idw;           // the first pass's method (the run's; dg-harmonic for laplacian)
    MethodOptions options;
    int dim = 3;
    std::vector<double> points;               // the small problem's points: the other boundary nodes, then the sliding ones
    std::vector<std::int32_t> source_slots;   // per other boundary node: its index in the run's BoundarySet
    BoundarySet boundary;                     // the small problem's: its first source_slots.size() points
    SlideSet slides;                          // the sliding nodes (ResolvedBoundary::slides)
    Plan plan;
};

/// The first pass of `method` for `resolved`'s sliding nodes (empty when
/// there are none: check resolved.slides.empty() first). Laplacian solves on
/// cells, which the small problem has none of: its first pass is DG-harmonic's.
SlidePass prepare_slide_pass(Method method, const Mesh& mesh, const ResolvedBoundary& resolved,
                             const MethodOptions& options = {});

/// Gives the sliding nodes of `motion` (one NodeMotion per node of the run's
/// BoundarySet) their translation for this frame: the first pass's
/// displacement, put into the node's planes. Throws as deform does.
void slide_motion(const SlidePass& pass, BoundaryMotion& motion);

}  // namespace dgwarp
