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
    Method method = Method::rbf;              // the first pass's (slide_pass_method)
    MethodOptions options;
    int dim = 3;
    /// DG-harmonic's first pass runs on the whole mesh (its points and the
    /// boundary nodes but the sliding ones); the other methods' on a small
    /// problem: the other boundary nodes, then the sliding ones.
    bool whole_mesh = false;
    std::vector<double> points;               // the problem's points
    std::vector<std::int32_t> source_slots;   // per other boundary node: its index in the run's BoundarySet
    BoundarySet boundary;                     // the problem's: the other boundary nodes (in source_slots order)
    SlideSet slides;                          // the sliding nodes (ResolvedBoundary::slides)
    Plan plan;
};

/// The most other boundary nodes (every boundary node but the sliding ones)
/// for which the first pass is RBF's (a dense system of that size: 32 MB).
inline constexpr std::size_t max_slide_rbf_centres = 2000;

/// The first pass's method, whatever the run's (the same sliding motion for
/// every method): global RBF, every other boundary node a centre, when there
/// are at most max_slide_rbf_centres of them; else DG-harmonic on the whole
/// mesh. Measured (2026-11-28; min quality of the step proper with
/// dg-harmonic): on random 2D scenes (`dgwarp case random`, seeds 3, 7, 11, 19,
/// 23) with their walls sliding, the RBF first pass keeps all five valid
/// (0.26, 0.0037, 0.33, 0.018, 0.073); each method's own first pass on the
/// small problem folded one of them (dg-harmonic seed 7, DG-IDW seed 23,
/// global IDW all five), DG-harmonic on the whole mesh seed 19, laplacian
/// seeds 3 and 7. On movingCone (axisymmetric, its axis and far fields
/// sliding, the cone moved 1 and 2 mm) only the RBF first pass is valid at
/// both: DG-harmonic's and DG-IDW's move the axis nodes unevenly (0.003 to
/// 0.1 of the motion from node to node), which folds the cells on it.
Method slide_pass_method(const ResolvedBoundary& resolved);

/// The first pass for `resolved`'s sliding nodes (empty when there are none:
/// check resolved.slides.empty() first); the run's method does not change it
/// (slide_pass_method), `options` are passed on (but RBF's: global, no reduction).
SlidePass prepare_slide_pass(const Mesh& mesh, const ResolvedBoundary& resolved, const MethodOptions& options = {});

/// Gives the sliding nodes of `motion` (one NodeMotion per node of the run's
/// BoundarySet) their translation for this frame: the first pass's
/// displacement, put into the node's planes. Throws as deform does.
void slide_motion(const SlidePass& pass, BoundaryMotion& motion);

}  // namespace dgwarp
