#pragma once
// The quality driver: per-cell shape quality over a whole mesh (threaded,
// deterministic), its summary, and the per-cell ratio deformed / original.
#include <cstdint>
#include <span>
#include <vector>

#include "dgwarp/mesh/mesh.hpp"

namespace dgwarp {

/// Per-cell reference orientation (+1/-1, see cell_orientation) of the
/// undeformed mesh, size reference.cells.size(); pass it to cell_qualities for
/// every deformed version. Threaded.
std::vector<std::int8_t> cell_orientations(const Mesh& reference);

/// The orientation most cells of `mesh` have (+1 on ties), used when a mesh is
/// judged on its own: a cell oriented against the majority counts as inverted.
/// The majority is taken separately per cell type, and every cell gets the
/// majority of its type (files may write, e.g., triangles clockwise and
/// quadrilaterals counter-clockwise); size mesh.cells.size().
std::vector<std::int8_t> dominant_orientations(const Mesh& mesh);
/// The same from the cells' own orientations (cell_orientations(mesh)), already computed.
std::vector<std::int8_t> dominant_orientations(const Mesh& mesh, std::vector<std::int8_t> own);

/// Shape quality of every cell (cell_shape_quality; size mesh.cells.size()),
/// judged against `orientations` (size mesh.cells.size()). Threaded (each cell
/// is computed on its own); the result is independent of the thread count.
std::vector<double> cell_qualities(const Mesh& mesh, std::span<const std::int8_t> orientations);
/// The same for the cells of `mesh` at other coordinates `points` (num_points
/// × dim, e.g. a deformed copy of mesh.points), without copying the mesh.
std::vector<double> cell_qualities(const Mesh& mesh, std::span<const double> points,
                                   std::span<const std::int8_t> orientations);

struct QualityLayout;  // quality_layout.hpp

/// cell_qualities and cell_orientations over a layout of `mesh`
/// (make_quality_layout): the same values to the bit, several times faster
/// on a mesh of simplices (the points copied in the layout's order, the
/// simplices by a vectorised kernel). A layout that does not fit the mesh
/// (QualityLayout::fits) takes the cells one by one, as above.
std::vector<double> cell_qualities(const QualityLayout& layout, const Mesh& mesh, std::span<const double> points,
                                   std::span<const std::int8_t> orientations);
std::vector<std::int8_t> cell_orientations(const QualityLayout& layout, const Mesh& mesh);
/// What a run measures of the original mesh, over a layout: its cells' own
/// orientations (cell_orientations) in `own`, the majority per cell type
/// (dominant_orientations) in `orientation`, and the quality of every cell
/// judged by that (cell_qualities) returned; the same values to the bit, in
/// one pass over the simplices instead of two (their quality against +1,
/// then signed: simplex_kernel.hpp).
std::vector<double> original_qualities(const QualityLayout& layout, const Mesh& mesh, std::vector<std::int8_t>& own,
                                       std::vector<std::int8_t>& orientation);

struct QualityHistogram {
    std::vector<double> edges;          // bin edges, size counts.size() + 1; first bin is (-inf, 0]
    std::vector<std::int64_t> counts;   // cells per bin
};

struct QualitySummary {
    std::int64_t cells = 0;
    double min = 0;              // smallest quality (<= 0 when a cell is inverted)
    double mean = 0;
    std::int64_t inverted = 0;   // cells with quality <= 0
    std::int64_t worst_cell = -1;  // index of a cell with the smallest quality (the first one)
    QualityHistogram histogram;  // bins: (-inf,0], (0,0.1], ..., (0.9,1]
};

/// Min, mean, inverted count and histogram of per-cell qualities (one per
/// cell). The mean is a compensated sum in cell order, so it is deterministic.
/// A value <= 0 counts as inverted and goes in the first bin; values slightly
/// above 1 (round-off) go in the last bin. Empty input: cells 0,
/// min = mean = 0, worst_cell -1, all counts 0.
QualitySummary summarize_quality(std::span<const double> qualities);

/// Cells the deformation inverted: quality <= 0 (or NaN) in `deformed` but
/// > 0 in `original` (same size, one value per cell), in cell order. Cells
/// that were already inverted or degenerate in the original are not among
/// them: the motion did not make them so.
std::vector<std::int64_t> newly_inverted_cells(std::span<const double> deformed, std::span<const double> original);

struct RatioSummary {
    double min = 0;
    double mean = 0;
    std::int64_t worst_cell = -1;
};

/// Per-cell ratio deformed / original (the paper's Fig. 24); both inputs and
/// the result have one value per cell (same size). Cells whose original
/// quality is not positive get ratio 0.
std::vector<double> quality_ratios(std::span<const double> deformed, std::span<const double> original);

/// Min and mean (compensated sum in cell order) of quality_ratios, and the
/// first cell with the smallest ratio; worst_cell -1 for empty input.
RatioSummary summarize_ratios(std::span<const double> ratios);
/// summarize_ratios(quality_ratios(deformed, original)), the same bits,
/// without the array of ratios.
RatioSummary summarize_ratios(std::span<const double> deformed, std::span<const double> original);

}  // namespace dgwarp
