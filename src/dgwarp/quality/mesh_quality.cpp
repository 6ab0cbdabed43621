// The quality driver: per-cell shape quality over a mesh and its summaries.
#include "dgwarp/quality/mesh_quality.hpp"

#include <algorithm>
#include <array>
#include <cassert>
#include <cmath>
#include <iterator>
#include <limits>

#include "dgwarp/core/ordered_sum.hpp"
#include "dgwarp/core/parallel_for.hpp"
#include "dgwarp/core/prefetch.hpp"
#include "dgwarp/quality/cell_quality.hpp"

namespace dgwarp {

namespace {

constexpr int histogram_bins = 11;  // (-inf,0], (0,0.1], ..., (0.9,1]

/// Copies the coordinates (from `points`) of cell i into `out` (nodes × dim, row-major).
std::span<const double> cell_coords(const Mesh& mesh, std::span<const double> points, std::size_t i,
                                    std::array<double, 24>& out) {
    const auto nodes = mesh.cells.nodes_of(i);
    const std::size_t dim = static_cast<std::size_t>(mesh.dim);
    assert(nodes.size() * dim <= out.size());
    for (std::size_t n = 0; n < nodes.size(); ++n)
        for (std::size_t c = 0; c < dim; ++c) out[n * dim + c] = points[static_cast<std::size_t>(nodes[n]) * dim + c];
    return {out.data(), nodes.size() * dim};
}

/// Calls body(i, coords) for every cell i of `mesh` with its coordinates
/// from `points` (cell_coords), one contiguous range of cells per thread.
/// The nodes of the cell `ahead` places on are prefetched: a mesh's node
/// numbering seldom follows its cells (Gmsh's does not), and a cell's four
/// to eight points are then as many cache misses; asking for them early lets
/// the memory system fetch several cells' at once (on the 865k-node sphere's
/// 5.3M tetrahedra in Gmsh's numbering, cell_qualities on one thread went
/// from 225 to 118 ns a cell).
template <class Body>
void for_each_cell(const Mesh& mesh, std::span<const double> points, Body&& body) {
    constexpr std::int64_t ahead = 12;
    const auto n = static_cast<std::int64_t>(mesh.cells.size());
    const std::size_t dim = static_cast<std::size_t>(mesh.dim);
    parallel_for_chunks(n, [&](std::int64_t begin, std::int64_t end) {
        std::array<double, 24> coords;
        for (std::int64_t i = begin; i < end; ++i) {
            if (i + ahead < end)
                for (NodeId v : mesh.cells.nodes_of(static_cast<std::size_t>(i + ahead)))
                    prefetch_bytes(points.data() + static_cast<std::size_t>(v) * dim, dim * sizeof(double));
            const auto k = static_cast<std::size_t>(i);
            // Polygons and polyhedra (any number of nodes) are measured from the list itself.
            body(k, has_any_node_count(mesh.cells.types[k]) ? std::span<const double>()
                                                            : cell_coords(mesh, points, k, coords));
        }
    });
}

}  // namespace

std::vector<std::int8_t> cell_orientations(const Mesh& reference) {
    std::vector<std::int8_t> orientation(reference.cells.size());
    for_each_cell(reference, reference.points, [&](std::size_t k, std::span<const double> coords) {
        const CellType t = reference.cells.types[k];
        orientation[k] = static_cast<std::int8_t>(
            has_any_node_count(t) ? element_orientation(reference.cells, k, reference.dim, reference.points)
                                  : cell_orientation(t, coords, reference.dim));
    });
    return orientation;
}

std::vector<std::int8_t> dominant_orientations(const Mesh& mesh) {
    return dominant_orientations(mesh, cell_orientations(mesh));
}

std::vector<std::int8_t> dominant_orientations(const Mesh& mesh, std::vector<std::int8_t> orientation) {
    assert(orientation.size() == mesh.cells.size());
    // Balance of +1 over -1 cells per cell type: real files mix conventions by
    // type (SU2's square-cylinder test mesh has clockwise triangles and
    // counter-clockwise quadrilaterals), so a per-dimension majority would
    // call a whole valid type inverted.
    std::array<std::int64_t, std::size(all_cell_types)> balance{};
    for (std::size_t i = 0; i < orientation.size(); ++i)
        balance[static_cast<std::size_t>(mesh.cells.types[i])] += orientation[i];
    for (std::size_t i = 0; i < orientation.size(); ++i)
        orientation[i] = balance[static_cast<std::size_t>(mesh.cells.types[i])] < 0 ? -1 : 1;
    return orientation;
}

std::vector<double> cell_qualities(const Mesh& mesh, std::span<const std::int8_t> orientations) {
    return cell_qualities(mesh, mesh.points, orientations);
}

std::vector<double> cell_qualities(const Mesh& mesh, std::span<const double> points,
                                   std::span<const std::int8_t> orientations) {
    assert(orientations.size() == mesh.cells.size());
    assert(points.size() == mesh.points.size());
    std::vector<double> quality(mesh.cells.size());
    for_each_cell(mesh, points, [&](std::size_t k, std::span<const double> coords) {
        const CellType t = mesh.cells.types[k];
        quality[k] = has_any_node_count(t) ? element_shape_quality(mesh.cells, k, mesh.dim, points, orientations[k])
                                           : cell_shape_quality(t, coords, mesh.dim, orientations[k]);
    });
    return quality;
}

namespace {
/// The histogram bin of q: 0 for q <= 0 (or NaN), else the b in
/// [1, histogram_bins - 1] with edges[b] < q <= edges[b + 1] (the last bin
/// open above): guessed from 10 q, then settled by the comparisons a walk up
/// the edges makes, so the same bin as that walk.
int histogram_bin(double q, const std::vector<double>& edges) {
    if (!(q > 0)) return 0;
    constexpr int last = histogram_bins - 1;
    if (q > edges[last]) return last;
    int bin = std::clamp(static_cast<int>(q * 10.0), 1, last);  // q in (0, 0.9] here
    while (bin > 1 && !(q > edges[static_cast<std::size_t>(bin)])) --bin;
    while (bin < last && q > edges[static_cast<std::size_t>(bin) + 1]) ++bin;
    return bin;
}
}  // namespace

QualitySummary summarize_quality(std::span<const double> qualities) {
    QualitySummary s;
    s.histogram.edges.resize(histogram_bins + 1);
    s.histogram.edges[0] = -std::numeric_limits<double>::infinity();
    for (int b = 1; b <= histogram_bins; ++b) s.histogram.edges[b] = (b - 1) / 10.0;
    s.histogram.counts.assign(histogram_bins, 0);
    s.cells = static_cast<std::int64_t>(qualities.size());
    if (qualities.empty()) return s;

    // The sum in cell order (so that the mean does not depend on the thread
    // count) on one thread, the minimum and the histogram beside it (5.3M
    // cells: 47 ms on one thread).
    const auto add_up = [&] {
        OrderedSum sum;
        for (const double q : qualities) sum.add(q);
        s.mean = sum.value() / static_cast<double>(qualities.size());
    };
    const auto count = [&] {
        s.min = qualities[0];
        s.worst_cell = 0;
        for (std::size_t i = 0; i < qualities.size(); ++i) {
            const double q = qualities[i];
            if (q < s.min) {
                s.min = q;
                s.worst_cell = static_cast<std::int64_t>(i);
            }
            ++s.histogram.counts[static_cast<std::size_t>(histogram_bin(q, s.histogram.edges))];
        }
        s.inverted = s.histogram.counts[0];  // q <= 0 or NaN
    };
    if (qualities.size() >= 16 * static_cast<std::size_t>(parallel_grain)) {
        run_concurrently(add_up, count);
    } else {
        add_up();
        count();
    }
    return s;
}

std::vector<std::int64_t> newly_inverted_cells(std::span<const double> deformed, std::span<const double> original) {
    assert(deformed.size() == original.size());
    std::vector<std::int64_t> cells;
    for (std::size_t i = 0; i < deformed.size(); ++i)
        if (original[i] > 0 && !(deformed[i] > 0)) cells.push_back(static_cast<std::int64_t>(i));
    return cells;
}

namespace {
double quality_ratio(double deformed, double original) { return original > 0 ? deformed / original : 0.0; }

/// summarize_ratios over ratio(i) for i in [0, n).
template <class Ratio>
RatioSummary summarize_ratio_values(std::size_t n, const Ratio& ratio) {
    RatioSummary s;
    if (n == 0) return s;
    OrderedSum sum;
    s.min = ratio(0);
    s.worst_cell = 0;
    for (std::size_t i = 0; i < n; ++i) {
        const double r = ratio(i);
        sum.add(r);
        if (r < s.min) {
            s.min = r;
            s.worst_cell = static_cast<std::int64_t>(i);
        }
    }
    s.mean = sum.value() / static_cast<double>(n);
    return s;
}
}  // namespace

std::vector<double> quality_ratios(std::span<const double> deformed, std::span<const double> original) {
    assert(deformed.size() == original.size());
    std::vector<double> ratio(deformed.size());
    for (std::size_t i = 0; i < ratio.size(); ++i) ratio[i] = quality_ratio(deformed[i], original[i]);
    return ratio;
}

RatioSummary summarize_ratios(std::span<const double> ratios) {
    return summarize_ratio_values(ratios.size(), [&](std::size_t i) { return ratios[i]; });
}

RatioSummary summarize_ratios(std::span<const double> deformed, std::span<const double> original) {
    assert(deformed.size() == original.size());
    return summarize_ratio_values(deformed.size(), [&](std::size_t i) { return quality_ratio(deformed[i], original[i]); });
}

}  // namespace dgwarp
