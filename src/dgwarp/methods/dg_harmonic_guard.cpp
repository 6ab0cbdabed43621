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
#include "dgwarp/quality/cell_quality.hpp"
#include "dgwarp/quality/corner_jacobian.hpp"
#include "dgwarp/quality/mesh_quality.hpp"

namespace dgwarp {

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
    // Judged as `dgwarp quality` judges a mesh on its own: against the
    // majority orientation of each cell type. A cell already inverted or
    // flat in the original is not the step's doing and is not judged.
    guard->orientations = dominant_orientations(guard->mesh);
    std::vector<std::uint8_t> on_boundary(points.size() / static_cast<std::size_t>(dim), 0);
    for (NodeId n : boundary.nodes) on_boundary[static_cast<std::size_t>(n)] = 1;
    guard->judged.resize(cells.size());
    for (std::size_t c = 0; c < cells.size(); ++c) {
        const auto nodes = cells.nodes_of(c);
        const bool all = std::all_of(nodes.begin(), nodes.end(),
                                     [&](NodeId n) { return on_boundary[static_cast<std::size_t>(n)] != 0; });
        guard->judged[c] = all ? 2 : 1;
    }
    const GuardMeasure original = measure_for_guard(*guard, points);
    if (original.inverted > 0) {
        const std::vector<double> quality = cell_qualities(guard->mesh, guard->orientations);
        for (std::size_t c = 0; c < quality.size(); ++c)
            if (!(quality[c] > 0)) guard->judged[c] = 0;
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
/// "key" with its cell (key: the metric cubed for tetrahedra, the metric
/// itself otherwise; an inverted cell's key is its (non-positive) metric).
struct BlockMeasure {
    std::int64_t inverted = 0, inverted_on_boundary = 0;
    double key = std::numeric_limits<double>::infinity();
    std::int64_t cell = -1;
};

/// The metric's exact value, as cell_shape_quality gives it.
double exact_quality(const DgHarmonicGuard& g, std::span<const double> points, std::size_t c) {
    const auto nodes = g.mesh.cells.nodes_of(c);
    const auto dim = static_cast<std::size_t>(g.mesh.dim);
    std::array<double, 24> coords{};
    for (std::size_t i = 0; i < nodes.size(); ++i)
        for (std::size_t d = 0; d < dim; ++d) coords[i * dim + d] = points[static_cast<std::size_t>(nodes[i]) * dim + d];
    return cell_shape_quality(g.mesh.cells.types[c], std::span<const double>(coords.data(), nodes.size() * dim),
                              g.mesh.dim, g.orientations[c]);
}

/// A tetrahedron's key: q^3 = 54 alpha^2 / den^3 when it is valid (q =
/// 3 (sqrt 2 alpha)^(2/3) / den, simplex_quality.cpp, from the same corner
/// Jacobian); false when it is not (the exact value decides). A monotone
/// function of q for q > 0.
inline bool tetrahedron_key(const double* x0, const double* x1, const double* x2, const double* x3, int orientation,
                            double& key) {
    const auto point = [](const double* x) { return Point3{x[0], x[1], x[2]}; };
    const quality_detail::CornerJacobian j =
        quality_detail::corner_jacobian(point(x0), point(x1), point(x2), point(x3));
    const double alpha = orientation * j.alpha;
    const double den = 1.5 * (j.l11 + j.l22 + j.l33) - (j.l12 + j.l23 + j.l13);
    if (!(alpha > 0) || !(den > 0)) return false;
    const double r = alpha / den;
    key = 54 * r * r / den;
    return std::isfinite(key) && key > 0;
}

}  // namespace

GuardMeasure measure_for_guard(const DgHarmonicGuard& g, std::span<const double> points) {
    const auto n = static_cast<std::int64_t>(g.mesh.cells.size());
    constexpr std::int64_t block = 1 << 14;
    const std::int64_t blocks = (n + block - 1) / block;
    std::vector<BlockMeasure> parts(static_cast<std::size_t>(blocks));
    const bool tetrahedra = g.mesh.dim == 3;
    parallel_for(
        blocks,
        [&](std::int64_t b) {
            BlockMeasure m;
            const ElementList& cells = g.mesh.cells;
            for (std::int64_t i = b * block; i < std::min(n, (b + 1) * block); ++i) {
                const auto c = static_cast<std::size_t>(i);
                if (!g.judged[c]) continue;
                double key = 0;
                bool fast = false;
                if (tetrahedra && cells.types[c] == CellType::tetrahedron) {
                    const NodeId* v = cells.nodes.data() + cells.offsets[c];
                    const double* p = points.data();
                    fast = tetrahedron_key(p + 3 * v[0], p + 3 * v[1], p + 3 * v[2], p + 3 * v[3], g.orientations[c],
                                           key);
                }
                if (!fast) {
                    const double q = exact_quality(g, points, c);
                    if (!(q > 0)) {
                        ++m.inverted;
                        m.inverted_on_boundary += g.judged[c] == 2;
                        key = std::isnan(q) ? -1.0 : q;
                    } else {
                        key = tetrahedra ? q * q * q : q;  // 3D: every key on the cube, as the kernel's
                    }
                }
                if (key < m.key) m.key = key, m.cell = i;
            }
            parts[static_cast<std::size_t>(b)] = m;
        },
        1);
    BlockMeasure all;
    for (const BlockMeasure& m : parts) {
        all.inverted += m.inverted;
        all.inverted_on_boundary += m.inverted_on_boundary;
        if (m.key < all.key) all.key = m.key, all.cell = m.cell;
    }
    GuardMeasure out;
    out.inverted = all.inverted;
    out.inverted_on_boundary = all.inverted_on_boundary;
    out.min_quality = all.cell < 0 ? 0 : exact_quality(g, points, static_cast<std::size_t>(all.cell));
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
    r.one_pass = measure_for_guard(guard, out);
    r.bar = redo_below * guard.original_min;
    if (r.one_pass.inverted == 0 && r.one_pass.min_quality >= r.bar) return r;
    if (r.one_pass.inverted_on_boundary > 0) {
        r.boundary_folds = true;
        return r;
    }
    r.redone = true;
    Stopwatch sw;
    std::vector<double> redo(out.size());
    try {
        r.increments = deform_laplacian(laplacian_plan_of(guard), points, motion, redo).increments;
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
    s << std::setprecision(3) << "one pass " << measure_text(r.one_pass) << " (bar " << r.bar << ")";
    if (r.boundary_folds)
        return s.str() + ": kept, not solved again (the boundary motion itself folds " +
               std::to_string(r.one_pass.inverted_on_boundary) + " cell" +
               (r.one_pass.inverted_on_boundary == 1 ? "" : "s") + ")";
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
           bytes_of(g.mesh.cells.nodes) + bytes_of(g.orientations) + bytes_of(g.judged) + bytes_of(g.boundary.nodes) +
           bytes_of(g.boundary.moving) + plan_bytes(g.laplacian);
}

}  // namespace dgwarp
