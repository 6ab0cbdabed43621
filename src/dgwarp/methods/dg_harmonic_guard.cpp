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
#include "dgwarp/methods/method_inputs.hpp"
#include "dgwarp/core/parallel_for.hpp"
#include "dgwarp/graph/morton_order.hpp"
#include "dgwarp/quality/cell_quality.hpp"
#include "dgwarp/quality/corner_jacobian.hpp"
#include "dgwarp/quality/mesh_quality.hpp"

namespace dgwarp {

namespace {
/// Fills the guard's measure layout (simplex_nodes, simplex_flags, other_cells)
/// from its judged cells, the simplices' flags signed by `simplex_orientation`.
void build_measure_layout(DgHarmonicGuard& g, int simplex_orientation);
/// dominant_orientations of the guard's mesh, counted in the layout's order.
std::vector<std::int8_t> layout_orientations(const DgHarmonicGuard& g);
/// The first simplex of the mesh (cells.size() when there is none).
std::size_t first_simplex(const DgHarmonicGuard& g);
}  // namespace

std::shared_ptr<const DgHarmonicGuard> make_dg_harmonic_guard(int dim, std::span<const double> points,
                                                              const ElementList& cells, const BoundarySet& boundary,
                                                              const LaplacianOptions& laplacian) {
    // Cells of the dimension, ids in range, the laplacian options.
    check_laplacian_inputs(dim, points, cells, boundary, laplacian, "DG-harmonic's guard (laplacian)");
    auto guard = std::make_shared<DgHarmonicGuard>();
    guard->mesh.dim = dim;
    guard->mesh.points.assign(points.begin(), points.end());
    guard->mesh.cells = cells;
    guard->boundary = boundary;
    guard->laplacian_options = laplacian;
    std::vector<std::uint8_t> on_boundary(points.size() / static_cast<std::size_t>(dim), 0);
    for (NodeId n : boundary.nodes) on_boundary[static_cast<std::size_t>(n)] = 1;
    guard->judged.resize(cells.size());
    for (std::size_t c = 0; c < cells.size(); ++c) {
        const auto nodes = cells.nodes_of(c);
        const bool all = std::all_of(nodes.begin(), nodes.end(),
                                     [&](NodeId n) { return on_boundary[static_cast<std::size_t>(n)] != 0; });
        guard->judged[c] = all ? 2 : 1;
    }
    // Judged as `dgwarp quality` judges a mesh on its own: against the
    // majority orientation of each cell type (dominant_orientations), here
    // counted on the layout's Morton order, which gathers far fewer points
    // from memory than the mesh's. A cell already inverted or flat in the
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

LaplacianOptions guard_laplacian_options(const LaplacianOptions& laplacian, const DgHarmonicOptions& harmonic) {
    LaplacianOptions o = laplacian;
    o.max_increments = std::max(o.increments, std::min(o.max_increments, harmonic.redo_max_increments));
    return o;
}

const LaplacianPlan& laplacian_plan_of(const DgHarmonicGuard& guard) {
    std::call_once(guard.laplacian_once, [&] {
        guard.laplacian = prepare_laplacian(guard.mesh.dim, guard.mesh.points, guard.mesh.cells, guard.boundary,
                                            guard.laplacian_options);
    });
    return guard.laplacian;
}

namespace {

using quality_detail::Point3;

/// One block's share of the measure: inverted count, and the smallest
/// "key" with where it is (key: the metric cubed for tetrahedra, the metric
/// itself otherwise; an inverted cell's key is its (non-positive) metric).
struct BlockMeasure {
    std::int64_t inverted = 0, inverted_on_boundary = 0;
    double key = std::numeric_limits<double>::infinity();
    std::int64_t simplex = -1;  // position in the layout's simplices, or
    std::int64_t cell = -1;     // a cell of another type
};

/// A cell's metric as cell_shape_quality gives it, from its nodes.
double exact_quality(int dim, CellType type, std::span<const NodeId> nodes, std::span<const double> points,
                     int orientation) {
    const auto d = static_cast<std::size_t>(dim);
    std::array<double, 24> coords{};
    for (std::size_t i = 0; i < nodes.size(); ++i)
        for (std::size_t k = 0; k < d; ++k) coords[i * d + k] = points[static_cast<std::size_t>(nodes[i]) * d + k];
    return cell_shape_quality(type, std::span<const double>(coords.data(), nodes.size() * d), dim, orientation);
}

CellType simplex_type(int dim) { return dim == 3 ? CellType::tetrahedron : CellType::triangle; }

std::span<const NodeId> simplex_at(const DgHarmonicGuard& g, std::int64_t s) {
    const auto n = static_cast<std::size_t>(g.mesh.dim + 1);
    return {g.simplex_nodes.data() + static_cast<std::size_t>(s) * n, n};
}

/// Whether a valid simplex's key, numerator / denominator, may be below
/// `key`: one multiplication instead of a division for the cells that are
/// plainly not a new minimum (most of them). A margin of 1e-12 (far above
/// the few roundings between this product and the caller's quotient) sends
/// near-ties to the caller, which divides and compares as before, so the
/// minimum found is the quotient's. A denominator too small for the product
/// to be exact (subnormal) or too large (infinite) says yes too.
inline bool below(double numerator, double denominator, double key) {
    return !(denominator >= std::numeric_limits<double>::min()) || !std::isfinite(denominator) ||
           numerator < key * denominator * (1 + 1e-12);
}

/// Updates `m` with simplex `s` of the layout (tetrahedra: the key is q^3 =
/// 54 alpha^2 / den^3, with q = 3 (sqrt 2 alpha)^(2/3) / den from the same
/// corner Jacobian as simplex_quality.cpp; triangles: q = sqrt 3 alpha / den).
/// A simplex that is not plainly valid takes the exact value.
template <int Dim>
inline void measure_simplex(const DgHarmonicGuard& g, std::span<const double> points, std::int64_t s,
                            BlockMeasure& m) {
    const std::int8_t flag = g.simplex_flags[static_cast<std::size_t>(s)];
    const NodeId* v = g.simplex_nodes.data() + static_cast<std::size_t>(s) * (Dim + 1);
    const double* p = points.data();
    const double orientation = flag > 0 ? 1.0 : -1.0;
    if constexpr (Dim == 3) {
        const auto point = [&](NodeId n) {
            const double* x = p + 3 * static_cast<std::size_t>(n);
            return Point3{x[0], x[1], x[2]};
        };
        const quality_detail::CornerJacobian j =
            quality_detail::corner_jacobian(point(v[0]), point(v[1]), point(v[2]), point(v[3]));
        const double alpha = orientation * j.alpha;
        const double den = 1.5 * (j.l11 + j.l22 + j.l33) - (j.l12 + j.l23 + j.l13);
        if (alpha > 0 && den > 0) {
            if (!below(54 * alpha * alpha, den * den * den, m.key)) return;
            const double r = alpha / den;
            const double key = 54 * r * r / den;
            if (std::isfinite(key) && key > 0) {
                if (key < m.key) m.key = key, m.simplex = s;
                return;
            }
        }
    } else {
        const double* x0 = p + 2 * static_cast<std::size_t>(v[0]);
        const double* x1 = p + 2 * static_cast<std::size_t>(v[1]);
        const double* x2 = p + 2 * static_cast<std::size_t>(v[2]);
        const double a1x = x1[0] - x0[0], a1y = x1[1] - x0[1], a2x = x2[0] - x0[0], a2y = x2[1] - x0[1];
        const double alpha = orientation * (a1x * a2y - a1y * a2x);
        const double den = (a1x * a1x + a1y * a1y) + (a2x * a2x + a2y * a2y) - (a1x * a2x + a1y * a2y);
        if (alpha > 0 && den > 0) {
            const double numerator = std::sqrt(3.0) * alpha;
            if (!below(numerator, den, m.key)) return;
            const double key = numerator / den;
            if (std::isfinite(key) && key > 0) {
                if (key < m.key) m.key = key, m.simplex = s;
                return;
            }
        }
    }
    const double q = exact_quality(Dim, simplex_type(Dim), simplex_at(g, s), points, static_cast<int>(orientation));
    double key;
    if (!(q > 0)) {
        ++m.inverted;
        m.inverted_on_boundary += flag == 2 || flag == -2;
        key = std::isnan(q) ? -1.0 : q;
    } else {
        key = Dim == 3 ? q * q * q : q;
    }
    if (key < m.key) m.key = key, m.simplex = s;
}

void build_measure_layout(DgHarmonicGuard& g, int simplex_orientation) {
    const ElementList& cells = g.mesh.cells;
    const CellType simplex = simplex_type(g.mesh.dim);
    const auto corners = static_cast<std::size_t>(g.mesh.dim + 1);
    const std::size_t num_points = g.mesh.num_points();
    // Each node's rank along a Morton curve; each judged simplex goes in the
    // bucket of its first node's rank (a counting sort: one pass, stable).
    std::vector<NodeId> all(num_points);
    for (std::size_t i = 0; i < num_points; ++i) all[i] = static_cast<NodeId>(i);
    const std::vector<std::uint32_t> order = morton_order(g.mesh.dim, g.mesh.points, all);
    std::vector<std::uint32_t> rank(num_points);
    for (std::size_t k = 0; k < order.size(); ++k) rank[order[k]] = static_cast<std::uint32_t>(k);
    std::vector<std::int64_t> start(num_points + 1, 0);
    g.other_cells.clear();
    for (std::size_t c = 0; c < cells.size(); ++c) {
        if (!g.judged[c]) continue;
        if (cells.types[c] == simplex)
            ++start[rank[static_cast<std::size_t>(cells.nodes[static_cast<std::size_t>(cells.offsets[c])])] + 1];
        else
            g.other_cells.push_back(static_cast<std::int64_t>(c));
    }
    for (std::size_t k = 0; k < num_points; ++k) start[k + 1] += start[k];
    const auto simplices = static_cast<std::size_t>(start[num_points]);
    g.simplex_nodes.assign(simplices * corners, 0);
    g.simplex_flags.assign(simplices, 0);
    for (std::size_t c = 0; c < cells.size(); ++c) {
        if (!g.judged[c] || cells.types[c] != simplex) continue;
        const auto nodes = cells.nodes_of(c);
        const auto s = static_cast<std::size_t>(start[rank[static_cast<std::size_t>(nodes[0])]]++);
        std::copy(nodes.begin(), nodes.end(), g.simplex_nodes.begin() + static_cast<std::ptrdiff_t>(s * corners));
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
    const auto corners = static_cast<std::size_t>(g.mesh.dim + 1);
    const auto d = static_cast<std::size_t>(g.mesh.dim);
    // Balance of +1 over -1 cells per type, as dominant_orientations counts
    // it (cell_orientation of each cell), the simplices in fixed blocks.
    constexpr std::int64_t block = 1 << 14;
    const auto simplices = static_cast<std::int64_t>(g.simplex_flags.size());
    const std::int64_t blocks = (simplices + block - 1) / block;
    std::vector<std::int64_t> parts(static_cast<std::size_t>(blocks), 0);
    parallel_for(
        blocks,
        [&](std::int64_t b) {
            std::int64_t sum = 0;
            std::array<double, 12> coords{};
            for (std::int64_t s = b * block; s < std::min(simplices, (b + 1) * block); ++s) {
                const NodeId* v = g.simplex_nodes.data() + static_cast<std::size_t>(s) * corners;
                for (std::size_t i = 0; i < corners; ++i)
                    for (std::size_t k = 0; k < d; ++k)
                        coords[i * d + k] = g.mesh.points[static_cast<std::size_t>(v[i]) * d + k];
                sum += cell_orientation(simplex, std::span<const double>(coords.data(), corners * d), g.mesh.dim);
            }
            parts[static_cast<std::size_t>(b)] = sum;
        },
        1);
    std::array<std::int64_t, std::size(all_cell_types)> balance{};
    for (std::int64_t p : parts) balance[static_cast<std::size_t>(simplex)] += p;
    // The layout holds the judged cells; the others (all of them, judged or
    // not, that are not in it) are counted one by one, as dominant_orientations does.
    for (std::size_t c = 0; c < cells.size(); ++c) {
        if (g.judged[c] && cells.types[c] == simplex) continue;
        std::array<double, 24> coords{};
        const auto nodes = cells.nodes_of(c);
        for (std::size_t i = 0; i < nodes.size(); ++i)
            for (std::size_t k = 0; k < d; ++k)
                coords[i * d + k] = g.mesh.points[static_cast<std::size_t>(nodes[i]) * d + k];
        balance[static_cast<std::size_t>(cells.types[c])] +=
            cell_orientation(cells.types[c], std::span<const double>(coords.data(), nodes.size() * d), g.mesh.dim);
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
    // Fixed blocks (not one per thread): the same minimum whatever the thread count.
    constexpr std::int64_t block = 1 << 14;
    const std::int64_t simplex_blocks = (simplices + block - 1) / block;
    const std::int64_t blocks = simplex_blocks + (others + block - 1) / block;
    std::vector<BlockMeasure> parts(static_cast<std::size_t>(blocks));
    const ElementList& cells = g.mesh.cells;
    parallel_for(
        blocks,
        [&](std::int64_t b) {
            BlockMeasure m;
            if (b < simplex_blocks) {
                const std::int64_t end = std::min(simplices, (b + 1) * block);
                for (std::int64_t s = b * block; s < end; ++s) {
                    if (g.mesh.dim == 3)
                        measure_simplex<3>(g, points, s, m);
                    else
                        measure_simplex<2>(g, points, s, m);
                }
            } else {
                const std::int64_t first = (b - simplex_blocks) * block;
                for (std::int64_t i = first; i < std::min(others, first + block); ++i) {
                    const auto c = static_cast<std::size_t>(g.other_cells[static_cast<std::size_t>(i)]);
                    const double q = exact_quality(g.mesh.dim, cells.types[c], cells.nodes_of(c), points,
                                                   g.orientations[c]);
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
        out.min_quality = exact_quality(g.mesh.dim, simplex_type(g.mesh.dim), simplex_at(g, all.simplex), points,
                                        orientation);
    } else if (all.cell >= 0) {
        const auto c = static_cast<std::size_t>(all.cell);
        out.min_quality = exact_quality(g.mesh.dim, cells.types[c], cells.nodes_of(c), points, g.orientations[c]);
    }
    if (std::isnan(out.min_quality)) out.min_quality = -1;
    return out;
}

namespace {
/// Whether result a is better than b: fewer inverted cells, then a higher minimum.
bool better(const GuardMeasure& a, const GuardMeasure& b) {
    if (a.inverted != b.inverted) return a.inverted < b.inverted;
    return a.min_quality > b.min_quality;
}
}  // namespace

DgHarmonicGuardReport deform_dg_harmonic_guarded(const DgHarmonicPlan& plan, std::span<const double> points,
                                                 const BoundaryMotion& motion, std::span<double> out,
                                                 double redo_below, const ProgressFn& progress) {
    if (std::isnan(redo_below) || redo_below >= 1)
        throw Error("DG-harmonic: redo_below must be below 1 (a fraction of the original minimum quality; negative: "
                    "never redo), got " + std::to_string(redo_below));
    DgHarmonicGuardReport r;
    // `out` may alias `points`: the redo needs the original points, so keep them.
    std::vector<double> kept;
    if (plan.guard && redo_below >= 0 && out.data() < points.data() + points.size() &&
        points.data() < out.data() + out.size()) {
        kept.assign(points.begin(), points.end());
        points = kept;
    }
    r.conflicting_shared_vertices = deform_dg_harmonic(plan, points, motion, out, progress).conflicting_shared_vertices;
    if (!plan.guard || redo_below < 0) return r;
    const DgHarmonicGuard& guard = *plan.guard;
    r.checked = true;
    Stopwatch measure_time;
    r.one_pass = measure_for_guard(guard, out);
    r.measure_seconds = measure_time.lap();
    r.bar = redo_below * guard.original_min;
    if (r.one_pass.inverted == 0 && r.one_pass.min_quality >= r.bar) return r;
    if (r.one_pass.inverted_on_boundary > 0) {
        r.boundary_folds = true;
        return r;
    }
    const auto nodes = static_cast<std::int64_t>(guard.mesh.num_points());
    if (plan.dim == 3 && nodes > plan.options.redo_max_nodes_3d) {
        // Not redone (redone stays false): the report says why.
        r.redo_error = "the mesh has " + std::to_string(nodes) + " nodes, more than the guard solves again in 3D (" +
                       std::to_string(plan.options.redo_max_nodes_3d) +
                       "): a laplacian solve of this size would take many minutes";
        return r;
    }
    r.redone = true;
    Stopwatch sw;
    std::vector<double> redo(out.size());
    try {
        // A valid one pass below the bar: one solve of laplacian's own
        // increments (a folded result would not be kept, so doubling them
        // could only cost: 4 + 8 + ... + 64 solves on the twisted bar).
        const LaplacianPlan& lp = laplacian_plan_of(guard);
        r.increments = deform_laplacian_capped(lp, points, motion, redo,
                                               r.one_pass.inverted == 0 ? lp.options.increments : lp.options.max_increments)
                           .increments;
    } catch (const InvalidResultError&) {
        throw;
    } catch (const Error& e) {
        // laplacian cannot solve this mesh (a part no boundary node holds,
        // found when its plan is built; a singular stiffness): the one pass
        // stays, and the report says why.
        r.redo_error = e.what();
        r.redo_seconds = sw.lap();
        return r;
    }
    r.redo = measure_for_guard(guard, redo);
    if (better(r.redo, r.one_pass)) {
        r.kept_redo = true;
        // Points no cell uses: laplacian leaves them; the one pass moved them with the rest.
        const auto dim = static_cast<std::size_t>(plan.dim);
        for (std::size_t node = 0; node < static_cast<std::size_t>(guard.laplacian.num_points); ++node)
            if (guard.laplacian.unknown[node] != -2)
                for (std::size_t d = 0; d < dim; ++d) out[node * dim + d] = redo[node * dim + d];
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
           bytes_of(g.simplex_nodes) + bytes_of(g.simplex_flags) + bytes_of(g.other_cells) + bytes_of(g.boundary.nodes) +
           bytes_of(g.boundary.moving) + plan_bytes(g.laplacian);
}

}  // namespace dgwarp
