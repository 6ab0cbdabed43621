// dg_harmonic_guard.hpp: DG-harmonic's step, measured, and solved again by
// the laplacian reference when the one pass folds or falls below the bar.
#include "dgwarp/methods/dg_harmonic_guard.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <iomanip>
#include <limits>
#include <sstream>

#include "dgwarp/core/error.hpp"
#include "dgwarp/core/stopwatch.hpp"
#include "dgwarp/methods/dg_harmonic.hpp"
#include "dgwarp/methods/guard_kernel.hpp"
#include "dgwarp/methods/method_inputs.hpp"
#include "dgwarp/core/parallel_for.hpp"
#include "dgwarp/quality/cell_quality.hpp"
#include "dgwarp/quality/mesh_quality.hpp"
#include "dgwarp/quality/quality_layout.hpp"

namespace dgwarp {

namespace {
/// The points in the guard's local order (DgHarmonicGuard::local_order;
/// quality_layout.hpp's points_in_order).
struct LocalPoints {
    std::unique_ptr<double[]> values;  // num_points × dim
    std::size_t num_points = 0;
};
LocalPoints local_points(const DgHarmonicGuard& g, std::span<const double> points);
/// Fills the guard's measure layout (simplex_nodes, simplex_flags, other_cells)
/// from its judged cells, the simplices' flags signed by `simplex_orientation`.
void build_measure_layout(DgHarmonicGuard& g, int simplex_orientation);
/// dominant_orientations of the guard's mesh, counted in the layout's order.
std::vector<std::int8_t> layout_orientations(const DgHarmonicGuard& g);
/// The first simplex of the mesh (cells.size() when there is none).
std::size_t first_simplex(const DgHarmonicGuard& g);
}  // namespace

namespace {
/// A guard with its boundary and laplacian options, the cells checked (of the
/// dimension, ids in range) as check_laplacian_cells checks them.
std::shared_ptr<DgHarmonicGuard> checked_guard(int dim, std::span<const double> points, const ElementList& cells,
                                               const BoundarySet& boundary, const LaplacianOptions& laplacian) {
    check_laplacian_inputs(dim, points, cells, boundary, laplacian, "DG-harmonic's guard (laplacian)");
    auto guard = std::make_shared<DgHarmonicGuard>();
    guard->mesh.dim = dim;
    guard->boundary = boundary;
    guard->laplacian_options = laplacian;
    return guard;
}
}  // namespace

std::shared_ptr<const DgHarmonicGuard> make_dg_harmonic_guard(int dim, std::span<const double> points,
                                                              const ElementList& cells, const BoundarySet& boundary,
                                                              const LaplacianOptions& laplacian) {
    auto guard = checked_guard(dim, points, cells, boundary, laplacian);
    guard->mesh.points.assign(points.begin(), points.end());
    guard->mesh.cells = cells;
    const std::size_t num_points = points.size() / static_cast<std::size_t>(dim);
    std::vector<std::uint8_t> on_boundary(num_points, 0);
    for (NodeId n : boundary.nodes) on_boundary[static_cast<std::size_t>(n)] = 1;
    guard->judged.resize(cells.size());
    for (std::size_t c = 0; c < cells.size(); ++c) {
        const auto nodes = cells.nodes_of(c);
        const bool all = std::all_of(nodes.begin(), nodes.end(),
                                     [&](NodeId n) { return on_boundary[static_cast<std::size_t>(n)] != 0; });
        guard->judged[c] = all ? 2 : 1;
    }
    guard->local_order = morton_numbering(dim, points);
    // Judged as `dgwarp quality` judges a mesh on its own: against the
    // majority orientation of each cell type (dominant_orientations), here
    // counted in the layout's order, which gathers far fewer points from
    // memory than the mesh's. A cell already inverted or flat in the
    // original is not the step's doing and is not judged.
    build_measure_layout(*guard, 1);
    guard->orientations = layout_orientations(*guard);
    if (guard->simplex_flags.size() > 0 && guard->orientations[first_simplex(*guard)] < 0)
        for (std::int8_t& f : guard->simplex_flags) f = static_cast<std::int8_t>(-f);
    const GuardMeasure original = measure_for_guard(*guard, points);
    if (original.inverted > 0) {
        const std::vector<double> quality = cell_qualities(guard->mesh, guard->orientations);
        for (std::size_t c = 0; c < quality.size(); ++c)
            if (!(quality[c] > 0)) guard->judged[c] = 0;
        const std::size_t simplex = first_simplex(*guard);
        build_measure_layout(*guard, simplex < cells.size() ? guard->orientations[simplex] : 1);
        guard->original_min = measure_for_guard(*guard, points).min_quality;
    } else {
        guard->original_min = original.min_quality;
    }
    return guard;
}

std::shared_ptr<const DgHarmonicGuard> make_frame_guard(int dim, std::span<const double> points,
                                                        const ElementList& cells, const BoundarySet& boundary,
                                                        const LaplacianOptions& laplacian) {
    auto guard = checked_guard(dim, points, cells, boundary, laplacian);
    guard->for_frames = true;
    return guard;
}

LaplacianOptions guard_laplacian_options(const LaplacianOptions& laplacian, const DgHarmonicOptions& harmonic) {
    LaplacianOptions o = laplacian;
    o.max_increments = std::max(o.increments, std::min(o.max_increments, harmonic.redo_max_increments));
    return o;
}

const LaplacianPlan& laplacian_plan_of(const DgHarmonicGuard& guard, std::span<const double> points,
                                       const ElementList& cells) {
    std::call_once(guard.laplacian_once, [&] {
        guard.laplacian = prepare_laplacian(guard.mesh.dim, points, cells, guard.boundary, guard.laplacian_options);
    });
    return guard.laplacian;
}

namespace {

/// Blocks of the guard's passes: fixed (not one per thread), so that the
/// minimum found is the same whatever the thread count.
constexpr std::int64_t pass_block = 1 << 14;

/// One block's share of the measure: inverted count, and the smallest
/// "key" with where it is (key: the metric cubed in 3D, the metric itself
/// in 2D; an inverted cell's key is its (non-positive) metric).
struct BlockMeasure {
    std::int64_t inverted = 0, inverted_on_boundary = 0;
    double key = std::numeric_limits<double>::infinity();
    std::int64_t simplex = -1;  // position in the layout's simplices, or
    std::int64_t cell = -1;     // a cell of another type
};

CellType simplex_type(int dim) { return dim == 3 ? CellType::tetrahedron : CellType::triangle; }

using guard_detail::kernel_block;

/// The local node ids of simplex s of the layout.
std::span<const NodeId> simplex_at(const DgHarmonicGuard& g, std::int64_t s) {
    const auto n = static_cast<std::size_t>(g.mesh.dim + 1);
    return {g.simplex_nodes.data() + static_cast<std::size_t>(s) * n, n};
}

/// The metric of simplex s of the layout as cell_shape_quality gives it, from the local points.
double exact_simplex_quality(const DgHarmonicGuard& g, const LocalPoints& local, std::int64_t s, int orientation) {
    const auto d = static_cast<std::size_t>(g.mesh.dim);
    const std::span<const NodeId> nodes = simplex_at(g, s);
    std::array<double, 12> coords{};
    for (std::size_t i = 0; i <= d; ++i)
        for (std::size_t k = 0; k < d; ++k) coords[i * d + k] = local.values[static_cast<std::size_t>(nodes[i]) * d + k];
    return cell_shape_quality(g.mesh.dim == 3 ? CellType::tetrahedron : CellType::triangle,
                              std::span<const double>(coords.data(), (d + 1) * d), g.mesh.dim, orientation);
}

LocalPoints local_points(const DgHarmonicGuard& g, std::span<const double> points) {
    return {points_in_order(g.local_order, g.mesh.dim, points), g.local_order.size()};
}

/// Runs the guard's kernel over the layout's simplices [first, end), on the
/// local points, a kernel block at a time: the block's edge vectors laid out
/// column by column, then the kernel, then visit(s, alpha, key) per simplex
/// (guard_kernel.hpp: alpha signed by the simplex's flag, key NaN when the
/// simplex is not plainly valid).
template <int Dim, class Visit>
void for_each_simplex_key_in(const DgHarmonicGuard& g, const LocalPoints& local, std::int64_t first,
                             std::int64_t end, Visit&& visit) {
    guard_detail::SimplexEdges edges;
    double alpha[kernel_block], key[kernel_block];
    const double* p = local.values.get();
    for (std::int64_t s0 = first; s0 < end; s0 += static_cast<std::int64_t>(kernel_block)) {
        const auto count = static_cast<std::size_t>(std::min<std::int64_t>(kernel_block, end - s0));
        const NodeId* v = g.simplex_nodes.data() + static_cast<std::size_t>(s0) * (Dim + 1);
        const std::int8_t* flag = g.simplex_flags.data() + s0;
        for (std::size_t i = 0; i < count; ++i, v += Dim + 1) {
            const double* x0 = p + Dim * static_cast<std::size_t>(v[0]);
            for (int k = 1; k <= Dim; ++k) {
                const double* xk = p + Dim * static_cast<std::size_t>(v[k]);
                for (int j = 0; j < Dim; ++j) edges.e[(k - 1) * Dim + j][i] = xk[j] - x0[j];
            }
            edges.sign[i] = flag[i] > 0 ? 1.0 : -1.0;
        }
        if constexpr (Dim == 3)
            guard_detail::tetrahedron_keys(edges, count, alpha, key);
        else
            guard_detail::triangle_keys(edges, count, alpha, key);
        for (std::size_t i = 0; i < count; ++i) visit(s0 + static_cast<std::int64_t>(i), alpha[i], key[i]);
    }
}
template <class Visit>
void for_each_simplex_key(const DgHarmonicGuard& g, const LocalPoints& local, std::int64_t first, std::int64_t end,
                          Visit&& visit) {
    if (g.mesh.dim == 3)
        for_each_simplex_key_in<3>(g, local, first, end, visit);
    else
        for_each_simplex_key_in<2>(g, local, first, end, visit);
}

/// The measure of the layout's simplices [first, end) on the local points.
void measure_simplices(const DgHarmonicGuard& g, const LocalPoints& local, std::int64_t first, std::int64_t end,
                       BlockMeasure& m) {
    const bool cubed = g.mesh.dim == 3;
    double best = m.key;
    std::int64_t where = m.simplex;
    for_each_simplex_key(g, local, first, end, [&](std::int64_t s, double, double key) {
        if (key < best) best = key, where = s;  // plainly valid: the usual case, and false for NaN
        if (key == key) return;
        const std::int8_t flag = g.simplex_flags[static_cast<std::size_t>(s)];
        const double q = exact_simplex_quality(g, local, s, flag > 0 ? 1 : -1);
        if (!(q > 0)) {
            ++m.inverted;
            m.inverted_on_boundary += flag == 2 || flag == -2;
            key = std::isnan(q) ? -1.0 : q;
        } else {
            key = cubed ? q * q * q : q;
        }
        if (key < best) best = key, where = s;
    });
    if (where != m.simplex) m.key = best, m.simplex = where, m.cell = -1;
}

void build_measure_layout(DgHarmonicGuard& g, int simplex_orientation) {
    const ElementList& cells = g.mesh.cells;
    const CellType simplex = simplex_type(g.mesh.dim);
    const auto corners = static_cast<std::size_t>(g.mesh.dim + 1);
    const std::size_t num_points = g.mesh.num_points();
    std::vector<NodeId> local_id(num_points);
    for (std::size_t k = 0; k < num_points; ++k) local_id[static_cast<std::size_t>(g.local_order[k])] = static_cast<NodeId>(k);
    // Each judged simplex goes in the group of its first node's local id
    // (512 ids to a group): a counting sort, one pass, stable.
    constexpr int group_shift = 9;
    const std::size_t groups = (num_points >> group_shift) + 1;
    const auto group_of = [&](NodeId first) {
        return static_cast<std::size_t>(local_id[static_cast<std::size_t>(first)]) >> group_shift;
    };
    std::vector<std::int64_t> start(groups + 1, 0);
    g.other_cells.clear();
    for (std::size_t c = 0; c < cells.size(); ++c) {
        if (!g.judged[c]) continue;
        if (cells.types[c] == simplex)
            ++start[group_of(cells.nodes[static_cast<std::size_t>(cells.offsets[c])]) + 1];
        else
            g.other_cells.push_back(static_cast<std::int64_t>(c));
    }
    for (std::size_t k = 0; k < groups; ++k) start[k + 1] += start[k];
    const auto simplices = static_cast<std::size_t>(start[groups]);
    g.simplex_nodes.assign(simplices * corners, 0);
    g.simplex_flags.assign(simplices, 0);
    for (std::size_t c = 0; c < cells.size(); ++c) {
        if (!g.judged[c] || cells.types[c] != simplex) continue;
        const NodeId* nodes = cells.nodes.data() + cells.offsets[c];
        const auto s = static_cast<std::size_t>(start[group_of(nodes[0])]++);
        for (std::size_t i = 0; i < corners; ++i)
            g.simplex_nodes[s * corners + i] = local_id[static_cast<std::size_t>(nodes[i])];
        g.simplex_flags[s] = static_cast<std::int8_t>(simplex_orientation * g.judged[c]);
    }
}

std::size_t first_simplex(const DgHarmonicGuard& g) {
    const CellType simplex = simplex_type(g.mesh.dim);
    const auto& types = g.mesh.cells.types;
    return static_cast<std::size_t>(std::find(types.begin(), types.end(), simplex) - types.begin());
}

std::vector<std::int8_t> layout_orientations(const DgHarmonicGuard& g) {
    const ElementList& cells = g.mesh.cells;
    const CellType simplex = simplex_type(g.mesh.dim);
    const auto d = static_cast<std::size_t>(g.mesh.dim);
    // Balance of +1 over -1 cells per type, as dominant_orientations counts
    // it (cell_orientation of each cell: -1 when α < 0), the simplices in
    // fixed blocks by the kernel; a simplex whose α is not finite (products
    // beyond the double range: cell_orientation scales its points) exactly.
    const LocalPoints local = local_points(g, g.mesh.points);
    const auto simplices = static_cast<std::int64_t>(g.simplex_flags.size());
    const std::int64_t blocks = (simplices + pass_block - 1) / pass_block;
    std::vector<std::int64_t> parts(static_cast<std::size_t>(blocks), 0);
    parallel_for(
        blocks,
        [&](std::int64_t b) {
            std::int64_t sum = 0;
            const auto count = [&](std::int64_t s, double alpha, double) {
                const double raw = g.simplex_flags[static_cast<std::size_t>(s)] > 0 ? alpha : -alpha;
                if (std::isfinite(raw)) {
                    sum += raw < 0 ? -1 : 1;
                    return;
                }
                std::array<double, 12> coords{};
                const std::span<const NodeId> nodes = simplex_at(g, s);
                for (std::size_t i = 0; i <= d; ++i)
                    for (std::size_t k = 0; k < d; ++k)
                        coords[i * d + k] = local.values[static_cast<std::size_t>(nodes[i]) * d + k];
                sum += cell_orientation(simplex, std::span<const double>(coords.data(), (d + 1) * d), g.mesh.dim);
            };
            for_each_simplex_key(g, local, b * pass_block, std::min(simplices, (b + 1) * pass_block), count);
            parts[static_cast<std::size_t>(b)] = sum;
        },
        1);
    std::array<std::int64_t, std::size(all_cell_types)> balance{};
    for (std::int64_t p : parts) balance[static_cast<std::size_t>(simplex)] += p;
    // The layout holds the judged cells; the others (all of them, judged or
    // not, that are not in it) are counted one by one, as dominant_orientations does.
    for (std::size_t c = 0; c < cells.size(); ++c) {
        if (g.judged[c] && cells.types[c] == simplex) continue;
        balance[static_cast<std::size_t>(cells.types[c])] += element_orientation(cells, c, g.mesh.dim, g.mesh.points);
    }
    std::vector<std::int8_t> orientation(cells.size());
    for (std::size_t c = 0; c < cells.size(); ++c)
        orientation[c] = balance[static_cast<std::size_t>(cells.types[c])] < 0 ? -1 : 1;
    return orientation;
}

}  // namespace

GuardMeasure measure_for_guard(const DgHarmonicGuard& g, std::span<const double> points) {
    const auto simplices = static_cast<std::int64_t>(g.simplex_flags.size());
    const auto others = static_cast<std::int64_t>(g.other_cells.size());
    const LocalPoints local = local_points(g, points);
    const std::int64_t simplex_blocks = (simplices + pass_block - 1) / pass_block;
    const std::int64_t blocks = simplex_blocks + (others + pass_block - 1) / pass_block;
    std::vector<BlockMeasure> parts(static_cast<std::size_t>(blocks));
    const ElementList& cells = g.mesh.cells;
    parallel_for(
        blocks,
        [&](std::int64_t b) {
            BlockMeasure m;
            if (b < simplex_blocks) {
                measure_simplices(g, local, b * pass_block, std::min(simplices, (b + 1) * pass_block), m);
            } else {
                const std::int64_t first = (b - simplex_blocks) * pass_block;
                for (std::int64_t i = first; i < std::min(others, first + pass_block); ++i) {
                    const auto c = static_cast<std::size_t>(g.other_cells[static_cast<std::size_t>(i)]);
                    const double q = element_shape_quality(cells, c, g.mesh.dim, points, g.orientations[c]);
                    double key;
                    if (!(q > 0)) {
                        ++m.inverted;
                        m.inverted_on_boundary += g.judged[c] == 2;
                        key = std::isnan(q) ? -1.0 : q;
                    } else {
                        key = g.mesh.dim == 3 ? q * q * q : q;  // 3D: every key on the cube, as the kernel's
                    }
                    if (key < m.key) m.key = key, m.simplex = -1, m.cell = static_cast<std::int64_t>(c);
                }
            }
            parts[static_cast<std::size_t>(b)] = m;
        },
        1);
    BlockMeasure all;
    for (const BlockMeasure& m : parts) {
        all.inverted += m.inverted;
        all.inverted_on_boundary += m.inverted_on_boundary;
        if (m.key < all.key) all = BlockMeasure{all.inverted, all.inverted_on_boundary, m.key, m.simplex, m.cell};
    }
    GuardMeasure out;
    out.inverted = all.inverted;
    out.inverted_on_boundary = all.inverted_on_boundary;
    if (all.simplex >= 0) {
        const int orientation = g.simplex_flags[static_cast<std::size_t>(all.simplex)] > 0 ? 1 : -1;
        out.min_quality = exact_simplex_quality(g, local, all.simplex, orientation);
    } else if (all.cell >= 0) {
        const auto c = static_cast<std::size_t>(all.cell);
        out.min_quality = element_shape_quality(cells, c, g.mesh.dim, points, g.orientations[c]);
    }
    if (std::isnan(out.min_quality)) out.min_quality = -1;
    return out;
}

std::span<const double> points_kept_from(std::span<const double> points, std::span<const double> out,
                                         std::vector<double>& kept) {
    if (out.data() < points.data() + points.size() && points.data() < out.data() + out.size()) {
        kept.assign(points.begin(), points.end());
        return kept;
    }
    return points;
}

void check_redo_below(double redo_below) {
    if (std::isnan(redo_below) || redo_below >= 1)
        throw Error("DG-harmonic: redo_below must be below 1 (a fraction of the original minimum quality; negative: "
                    "never redo), got " + std::to_string(redo_below));
}

bool guard_verdict(const DgHarmonicPlan& plan, const GuardMeasure& one_pass, double original_min, double redo_below,
                   DgHarmonicGuardReport& r) {
    r.checked = true;
    r.one_pass = one_pass;
    r.bar = redo_below * original_min;
    if (r.one_pass.inverted == 0 && r.one_pass.min_quality >= r.bar) return false;
    if (r.one_pass.inverted_on_boundary > 0) {
        r.boundary_folds = true;
        return false;
    }
    const std::int64_t nodes = plan.num_points();
    if (plan.dim == 3 && nodes > plan.options.redo_max_nodes_3d) {
        // Not redone (redone stays false): the report says why.
        r.redo_error = "the mesh has " + std::to_string(nodes) + " nodes, more than the guard solves again in 3D (" +
                       std::to_string(plan.options.redo_max_nodes_3d) +
                       "): a laplacian solve of this size would take many minutes";
        return false;
    }
    return true;
}

bool guard_redo(const DgHarmonicPlan& plan, const ElementList& cells, std::span<const double> points,
                const BoundaryMotion& motion, std::span<double> redo, DgHarmonicGuardReport& r) {
    r.redone = true;
    try {
        // A valid one pass below the bar: one solve of laplacian's own
        // increments (a folded result would not be kept, so doubling them
        // could only cost: 4 + 8 + ... + 64 solves on the twisted bar).
        const LaplacianPlan& lp = laplacian_plan_of(*plan.guard, points, cells);
        r.increments = deform_laplacian_capped(lp, points, motion, redo,
                                               r.one_pass.inverted == 0 ? lp.options.increments : lp.options.max_increments)
                           .increments;
        return true;
    } catch (const InvalidResultError&) {
        throw;
    } catch (const Error& e) {
        // laplacian cannot solve this mesh (a part no boundary node holds,
        // found when its plan is built; a singular stiffness): the one pass
        // stays, and the report says why.
        r.redo_error = e.what();
        return false;
    }
}

namespace {
/// Whether result a is better than b: fewer inverted cells, then a higher minimum.
bool better(const GuardMeasure& a, const GuardMeasure& b) {
    if (a.inverted != b.inverted) return a.inverted < b.inverted;
    return a.min_quality > b.min_quality;
}
}  // namespace

bool guard_keep(const DgHarmonicPlan& plan, std::span<const double> redo, std::span<double> out,
                DgHarmonicGuardReport& r) {
    if (!better(r.redo, r.one_pass)) return false;
    r.kept_redo = true;
    // Points no cell uses: laplacian leaves them; the one pass moved them with the rest.
    const LaplacianPlan& lp = plan.guard->laplacian;
    const auto dim = static_cast<std::size_t>(plan.dim);
    for (std::size_t node = 0; node < static_cast<std::size_t>(lp.num_points); ++node)
        if (lp.unknown[node] != -2)
            for (std::size_t d = 0; d < dim; ++d) out[node * dim + d] = redo[node * dim + d];
    return true;
}

DgHarmonicGuardReport deform_dg_harmonic_guarded(const DgHarmonicPlan& plan, std::span<const double> points,
                                                 const BoundaryMotion& motion, std::span<double> out,
                                                 double redo_below, const ProgressFn& progress) {
    check_redo_below(redo_below);
    DgHarmonicGuardReport r;
    std::vector<double> kept;
    const bool checks = plan.guard && !plan.guard->for_frames && redo_below >= 0;
    if (checks) points = points_kept_from(points, out, kept);
    r.conflicting_shared_vertices = deform_dg_harmonic(plan, points, motion, out, progress).conflicting_shared_vertices;
    if (!checks) return r;
    const DgHarmonicGuard& guard = *plan.guard;
    Stopwatch measure_time;
    const GuardMeasure one_pass = measure_for_guard(guard, out);
    r.measure_seconds = measure_time.lap();
    if (!guard_verdict(plan, one_pass, guard.original_min, redo_below, r)) return r;
    Stopwatch sw;
    std::vector<double> redo(out.size());
    if (guard_redo(plan, guard.mesh.cells, points, motion, redo, r)) {
        r.redo = measure_for_guard(guard, redo);
        guard_keep(plan, redo, out, r);
    }
    r.redo_seconds = sw.lap();
    return r;
}

namespace {
std::string measure_text(const GuardMeasure& m) {
    std::ostringstream s;
    s << std::setprecision(3) << "min " << m.min_quality;
    if (m.inverted > 0) s << ", " << m.inverted << " inverted";
    return s.str();
}
}  // namespace

std::string guard_summary(const DgHarmonicGuardReport& r) {
    if (!r.checked) return "";
    std::ostringstream s;
    s << std::setprecision(3) << "one pass " << measure_text(r.one_pass) << " (bar " << r.bar << ", measured in "
      << std::fixed << std::setprecision(1) << r.measure_seconds * 1e3 << " ms)" << std::defaultfloat
      << std::setprecision(3);
    if (r.boundary_folds)
        return s.str() + ": kept, not solved again (the boundary motion itself folds " +
               std::to_string(r.one_pass.inverted_on_boundary) + " cell" +
               (r.one_pass.inverted_on_boundary == 1 ? "" : "s") + ")";
    if (!r.redone && !r.redo_error.empty()) return s.str() + ": kept, not solved again (" + r.redo_error + ")";
    if (!r.redone) return s.str() + ": kept";
    s << ": solved again by laplacian";
    if (!r.redo_error.empty()) {
        s << ", which failed (" << r.redo_error << "); the one pass is kept";
    } else {
        s << " in " << r.increments << " increment" << (r.increments == 1 ? "" : "s") << ", " << measure_text(r.redo)
          << (r.kept_redo ? ", kept" : ", not better: the one pass is kept");
    }
    s << std::fixed << std::setprecision(1) << " (" << r.redo_seconds * 1e3 << " ms)";
    return s.str();
}

std::size_t guard_bytes(const DgHarmonicGuard& g) {
    return bytes_of(g.mesh.points) + bytes_of(g.mesh.cells.types) + bytes_of(g.mesh.cells.offsets) +
           bytes_of(g.mesh.cells.nodes) + bytes_of(g.orientations) + bytes_of(g.judged) +
           bytes_of(g.local_order) + bytes_of(g.simplex_nodes) + bytes_of(g.simplex_flags) + bytes_of(g.other_cells) + bytes_of(g.boundary.nodes) +
           bytes_of(g.boundary.moving) + plan_bytes(g.laplacian);
}

}  // namespace dgwarp
