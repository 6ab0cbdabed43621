// quality_layout.hpp: the layout, and the quality passes over it (mesh_quality.hpp).
#include "dgwarp/quality/quality_layout.hpp"

#include <algorithm>
#include <array>
#include <cassert>
#include <cmath>
#include <limits>
#include <memory>

#include "dgwarp/core/parallel_for.hpp"
#include "dgwarp/graph/morton_order.hpp"
#include "dgwarp/quality/cell_quality.hpp"
#include "dgwarp/quality/mesh_quality.hpp"
#include "dgwarp/quality/simplex_kernel.hpp"

namespace dgwarp {

namespace {

using quality_detail::simplex_block;

CellType simplex_type(int dim) { return dim == 3 ? CellType::tetrahedron : CellType::triangle; }

/// Blocks of the passes: fixed, so that the work does not depend on the thread count.
constexpr std::int64_t pass_block = 1 << 14;

}  // namespace

std::vector<NodeId> morton_numbering(int dim, std::span<const double> points) {
    std::vector<NodeId> all(points.size() / static_cast<std::size_t>(dim));
    for (std::size_t i = 0; i < all.size(); ++i) all[i] = static_cast<NodeId>(i);
    const std::vector<std::uint32_t> order = morton_order(dim, points, all);
    return {order.begin(), order.end()};
}

std::unique_ptr<double[]> points_in_order(std::span<const NodeId> order, int dim, std::span<const double> points,
                                          double* largest) {
    const auto d = static_cast<std::size_t>(dim);
    const std::size_t n = order.size();
    std::unique_ptr<double[]> local(new double[n * d]);
    double* out = local.get();
    const auto nodes = static_cast<std::int64_t>(n);
    const std::int64_t blocks = (nodes + pass_block - 1) / pass_block;
    std::vector<double> block_largest(static_cast<std::size_t>(blocks), 0.0);
    parallel_for(
        blocks,
        [&](std::int64_t b) {
            const auto end = static_cast<std::size_t>(std::min(nodes, (b + 1) * pass_block));
            double most = 0;
            for (auto k = static_cast<std::size_t>(b * pass_block); k < end; ++k) {
                const double* x = points.data() + static_cast<std::size_t>(order[k]) * d;
                for (std::size_t j = 0; j < d; ++j) {
                    out[k * d + j] = x[j];
                    most = std::fabs(x[j]) > most ? std::fabs(x[j]) : most;  // NaN passed over
                }
            }
            block_largest[static_cast<std::size_t>(b)] = most;
        },
        1);
    if (largest) *largest = block_largest.empty() ? 0.0 : *std::max_element(block_largest.begin(), block_largest.end());
    return local;
}

QualityLayout make_quality_layout(const Mesh& mesh) {
    QualityLayout g;
    const ElementList& cells = mesh.cells;
    if (cells.size() > std::numeric_limits<std::uint32_t>::max()) return g;
    g.dim = mesh.dim;
    g.num_points = mesh.num_points();
    g.num_cells = cells.size();
    g.local_order = morton_numbering(mesh.dim, mesh.points);
    std::vector<NodeId> local_id(g.num_points);
    for (std::size_t k = 0; k < g.num_points; ++k)
        local_id[static_cast<std::size_t>(g.local_order[k])] = static_cast<NodeId>(k);
    // The simplices in the cells' order, with local node ids.
    const CellType simplex = simplex_type(mesh.dim);
    const auto corners = static_cast<std::size_t>(mesh.dim + 1);
    const auto simplices =
        static_cast<std::size_t>(std::count(cells.types.begin(), cells.types.end(), simplex));
    g.simplex_nodes.resize(simplices * corners);
    g.simplex_cell.resize(simplices);
    g.other_cells.reserve(cells.size() - simplices);
    std::size_t s = 0;
    for (std::size_t c = 0; c < cells.size(); ++c) {
        if (cells.types[c] != simplex) {
            g.other_cells.push_back(static_cast<std::uint32_t>(c));
            continue;
        }
        const NodeId* nodes = cells.nodes.data() + cells.offsets[c];
        for (std::size_t i = 0; i < corners; ++i)
            g.simplex_nodes[s * corners + i] = local_id[static_cast<std::size_t>(nodes[i])];
        g.simplex_cell[s++] = static_cast<std::uint32_t>(c);
    }
    return g;
}

std::size_t layout_bytes(const QualityLayout& g) {
    return g.local_order.size() * sizeof(NodeId) + g.simplex_nodes.size() * sizeof(NodeId) +
           g.simplex_cell.size() * sizeof(std::uint32_t) + g.other_cells.size() * sizeof(std::uint32_t);
}

namespace {

/// The points in the layout's order; nullptr when a coordinate is beyond
/// 2^400 (or infinite): cell_shape_quality scales such cells' points first,
/// and the passes then take every cell one by one.
std::unique_ptr<double[]> local_points(const QualityLayout& g, std::span<const double> points) {
    double largest = 0;
    std::unique_ptr<double[]> local = points_in_order(g.local_order, g.dim, points, &largest);
    if (largest > 0x1p400) return nullptr;
    return local;
}

/// Calls kernel(block, count, results) on the layout's simplices [first, end)
/// a block at a time, the block's edge vectors laid out column by column
/// (sign from `orientations`, +1 without), then done(s, value) per simplex.
template <int Dim, class Kernel, class Done>
void for_each_simplex_block(const QualityLayout& g, const double* p, std::span<const std::int8_t> orientations,
                            std::int64_t first, std::int64_t end, Kernel&& kernel, Done&& done) {
    quality_detail::SimplexBlock block;
    double value[simplex_block];
    for (std::int64_t s0 = first; s0 < end; s0 += static_cast<std::int64_t>(simplex_block)) {
        const auto count = static_cast<std::size_t>(std::min<std::int64_t>(simplex_block, end - s0));
        const NodeId* v = g.simplex_nodes.data() + static_cast<std::size_t>(s0) * (Dim + 1);
        for (std::size_t i = 0; i < count; ++i, v += Dim + 1) {
            const double* x0 = p + Dim * static_cast<std::size_t>(v[0]);
            for (int k = 1; k <= Dim; ++k) {
                const double* xk = p + Dim * static_cast<std::size_t>(v[k]);
                for (int j = 0; j < Dim; ++j) block.e[(k - 1) * Dim + j][i] = xk[j] - x0[j];
            }
            block.sign[i] = orientations.empty() || orientations[g.simplex_cell[static_cast<std::size_t>(s0) + i]] >= 0
                                ? 1.0
                                : -1.0;
        }
        kernel(block, count, value);
        for (std::size_t i = 0; i < count; ++i) done(static_cast<std::size_t>(s0) + i, value[i]);
    }
}

/// The pass: per simplex kernel(...) then done(cell, value); the other cells one by one, other(cell).
template <class Kernel3, class Kernel2, class Done, class Other>
void layout_pass(const QualityLayout& g, const double* p, std::span<const std::int8_t> orientations,
                 Kernel3&& kernel3, Kernel2&& kernel2, Done&& done, Other&& other) {
    const auto simplices = static_cast<std::int64_t>(g.simplex_cell.size());
    const auto others = static_cast<std::int64_t>(g.other_cells.size());
    const std::int64_t simplex_blocks = (simplices + pass_block - 1) / pass_block;
    const std::int64_t blocks = simplex_blocks + (others + pass_block - 1) / pass_block;
    parallel_for(
        blocks,
        [&](std::int64_t b) {
            if (b < simplex_blocks) {
                const std::int64_t first = b * pass_block, end = std::min(simplices, first + pass_block);
                const auto to_cell = [&](std::size_t s, double value) { done(g.simplex_cell[s], value); };
                if (g.dim == 3)
                    for_each_simplex_block<3>(g, p, orientations, first, end, kernel3, to_cell);
                else
                    for_each_simplex_block<2>(g, p, orientations, first, end, kernel2, to_cell);
                return;
            }
            const std::int64_t first = (b - simplex_blocks) * pass_block;
            for (std::int64_t i = first; i < std::min(others, first + pass_block); ++i)
                other(g.other_cells[static_cast<std::size_t>(i)]);
        },
        1);
}

}  // namespace

std::vector<double> cell_qualities(const QualityLayout& layout, const Mesh& mesh, std::span<const double> points,
                                   std::span<const std::int8_t> orientations) {
    assert(orientations.size() == mesh.cells.size());
    const std::unique_ptr<double[]> local = layout.fits(mesh) ? local_points(layout, points) : nullptr;
    if (!local) return cell_qualities(mesh, points, orientations);
    std::vector<double> quality(mesh.cells.size());
    layout_pass(
        layout, local.get(), orientations, quality_detail::tetrahedron_qualities, quality_detail::triangle_qualities,
        [&](std::uint32_t c, double q) { quality[c] = q; },
        [&](std::uint32_t c) {
            quality[c] = element_shape_quality(mesh.cells, c, mesh.dim, points, orientations[c]);
        });
    return quality;
}

std::vector<std::int8_t> cell_orientations(const QualityLayout& layout, const Mesh& mesh) {
    const std::unique_ptr<double[]> local = layout.fits(mesh) ? local_points(layout, mesh.points) : nullptr;
    if (!local) return cell_orientations(mesh);
    std::vector<std::int8_t> orientation(mesh.cells.size());
    layout_pass(
        layout, local.get(), {}, quality_detail::tetrahedron_alphas, quality_detail::triangle_alphas,
        [&](std::uint32_t c, double alpha) { orientation[c] = static_cast<std::int8_t>(alpha < 0 ? -1 : 1); },
        [&](std::uint32_t c) {
            orientation[c] = static_cast<std::int8_t>(element_orientation(mesh.cells, c, mesh.dim, mesh.points));
        });
    return orientation;
}

}  // namespace dgwarp
