#pragma once
// The laplacian reference method (docs/laplacian.md): the displacement of
// every node solves a stiffened P1 problem on the whole mesh, by default
// linear elasticity (SU2's mesh deformation),
//
//   div(k sigma(u)) = 0 in the mesh,  u = the boundary motion's displacement
//   on the boundary nodes,            k = (V_mean / V_cell)^e,
//
// or the displacement Laplacian div(k grad u) = 0 (OpenFOAM's
// displacementLaplacian; one solve per component with the same matrix),
// in n increments: increment s
// moves the boundary from fraction (s-1)/n to s/n of its motion (a rotation
// along its arc: fraction f is c + R(f w)(x0 - c) + f t) and is assembled on
// the mesh as the earlier increments left it, so cells that shrink stiffen.
// When a simplex of the (split) mesh folds, the step is solved again with
// twice the increments (up to max_increments), and the report says how many.
// It is slow by design (a sparse factorisation per increment) and is the
// quality reference of the robustness campaign (dgwarp bench --robustness).
//
// Cells other than simplices are split conformingly: a centre node per cell
// and per quadrilateral face (shared by the face's two cells), each face
// joined to the cell centre (a triangle face: one tetrahedron; a quadrilateral
// face: four, through its centre; in 2D each edge of a quadrilateral: one
// triangle). Those extra nodes are unknowns too; the centre of a quadrilateral
// face on the boundary follows its corners' mean. Nodes that no cell uses keep
// their original coordinates.
//
// Unlike the other methods, it needs the mesh's cells:
//   prepare(Method::laplacian, dim, points, cells, boundary, options).
// Elasticity is the default: an infinitesimal rotation costs it no energy,
// so the cells next to a turning body turn with it, where the Laplacian
// shears them (the paper's rectangle turned 90°: min quality 0.34 against
// the Laplacian's 40 inverted cells; docs/laplacian.md).
// Conventions: points num_points × dim, row-major; 0-based node ids; motions
// one NodeMotion per boundary node in BoundarySet order. Each step is
// computed from the original points; results do not depend on the thread
// count (assembly and solve are serial).
#include <cstdint>
#include <span>
#include <string_view>
#include <vector>

#include "dgwarp/core/progress.hpp"
#include "dgwarp/mesh/mesh.hpp"
#include "dgwarp/motion/node_motion.hpp"

namespace dgwarp {

/// What the reference solves: linear elasticity (the components coupled), or
/// the displacement Laplacian per component.
enum class LaplacianModel { laplacian, elasticity };

struct LaplacianOptions {
    /// Increments per step, 1 to 64: more is slower and follows large
    /// rotations better (docs/laplacian.md has the measurements).
    int increments = 4;
    /// While a simplex of the split mesh folds, the step is solved again with
    /// twice the increments, up to this many (1 to 64; = increments: never).
    int max_increments = 64;
    /// e in the stiffness (V_mean / V_cell)^e, 0 to 4 (0: the plain Laplacian).
    double stiffness_exponent = 1.5;
    LaplacianModel model = LaplacianModel::elasticity;
    /// Elasticity: Poisson's ratio, in [0, 0.45].
    double poisson_ratio = 0.3;
};

/// The split mesh and its bookkeeping, as plain arrays. Nodes of the split
/// mesh: the mesh's points 0 .. num_points-1, then the centres
/// num_points .. num_points + num_centres - 1.
struct LaplacianPlan {
    int dim = 3;
    std::int64_t num_points = 0;
    LaplacianOptions options;
    std::vector<NodeId> boundary_nodes;         // BoundarySet::nodes (sorted)
    std::vector<std::uint8_t> boundary_moving;  // BoundarySet::moving
    /// num_simplices × (dim + 1) node ids of the split mesh.
    std::vector<std::int32_t> simplices;
    /// Per simplex, the mesh cell it comes from (its stiffness is the cell's).
    std::vector<std::int32_t> simplex_cell;
    /// The corner simplices of the cells that are not simplices (a corner and
    /// its dim neighbours), × (dim + 1): with the split's simplices, what must
    /// not fold (a quadrilateral can fold at a corner while its split does not).
    std::vector<std::int32_t> corners;
    std::int64_t num_cells = 0;
    /// Centre c: the mean of nodes centre_node[centre_start[c] .. centre_start[c+1]).
    std::vector<std::int64_t> centre_start{0};
    std::vector<NodeId> centre_node;
    /// Per split-mesh node: its unknown (>= 0), -1 for a boundary node or a
    /// boundary face's centre (given), -2 for a point no cell uses (stays).
    std::vector<std::int32_t> unknown;
    std::int32_t num_unknowns = 0;

    std::int64_t num_centres() const { return static_cast<std::int64_t>(centre_start.size()) - 1; }
};

/// What one step did.
struct LaplacianStepReport {
    int increments = 0;  // the increments of the solve kept (more than options.increments when folds asked for more)
    std::int64_t unknowns = 0;
};

/// The checks prepare_laplacian makes before any work (the throws below but
/// the last: a part no boundary node holds is found while splitting);
/// returns the number of points. `who` begins the messages ("laplacian").
std::size_t check_laplacian_inputs(int dim, std::span<const double> points, const ElementList& cells,
                                   const BoundarySet& boundary, const LaplacianOptions& options,
                                   std::string_view who);

/// Splits the cells and numbers the unknowns. `points`: num_points × dim,
/// original coordinates; `cells`: the mesh's cells (of dimension dim);
/// `boundary`: the boundary set. Throws MeshError for bad inputs (a cell of
/// another dimension, a node id out of range, no cells, a part of the mesh
/// that no boundary node holds), Error for bad options.
LaplacianPlan prepare_laplacian(int dim, std::span<const double> points, const ElementList& cells,
                                const BoundarySet& boundary, const LaplacianOptions& options = {});

/// One step from the original `points`: writes every node's new coordinates
/// to `out` (num_points × dim; may alias points). Boundary nodes move
/// exactly as apply_motion says. Throws MeshError on size mismatch or a
/// non-finite motion, Error when a solve fails (a part of the mesh that no
/// boundary node holds). `progress` gets the fraction of increments done.
LaplacianStepReport deform_laplacian(const LaplacianPlan& plan, std::span<const double> points,
                                     const BoundaryMotion& motion, std::span<double> out,
                                     const ProgressFn& progress = {});

/// deform_laplacian with the doubling of the increments capped at
/// min(max_increments, the plan's max_increments): at or below the plan's
/// increments, one solve of options.increments increments, folded or not
/// (DG-harmonic's guard, when the one pass it would replace is valid).
LaplacianStepReport deform_laplacian_capped(const LaplacianPlan& plan, std::span<const double> points,
                                            const BoundaryMotion& motion, std::span<double> out, int max_increments,
                                            const ProgressFn& progress = {});

/// Bytes held by the plan's arrays.
std::size_t plan_bytes(const LaplacianPlan& plan);

}  // namespace dgwarp
