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
    g.dim = mesh.dim;
    g.num_points = mesh.num_points();
    g.num_cells = mesh.cells.size();
    g.local_order = morton_numbering(mesh.dim, mesh.points);
    g.local_id.resize(g.num_points);
    const auto n = static_cast<std::int64_t>(g.num_points);
    parallel_for(n, [&](std::int64_t k) {
        g.local_id[static_cast<std::size_t>(g.local_order[static_cast<std::size_t>(k)])] = static_cast<NodeId>(k);
    });
    return g;
}

std::size_t layout_bytes(const QualityLayout& g) {
    return (g.local_order.size() + g.local_id.size()) * sizeof(NodeId);
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

/// The pass over cells [first, end): the simplices (type `simplex`) a
/// block at a time, their edge vectors laid out column by column from the
/// local points `p` (sign from `orientations`, +1 without), through
/// kernel(block, count, values, alphas), then done(cell, value, alpha) per
/// simplex (alpha: what the kernel wrote there, if anything); any other
/// cell by other(cell), in turn.
template <int Dim, class Kernel, class Done, class Other>
void pass_cells(const QualityLayout& g, const ElementList& cells, const double* p,
                std::span<const std::int8_t> orientations, std::int64_t first, std::int64_t end, Kernel&& kernel,
                Done&& done, Other&& other) {
    constexpr CellType simplex = Dim == 3 ? CellType::tetrahedron : CellType::triangle;
    quality_detail::SimplexBlock block;
    double value[simplex_block], alpha[simplex_block] = {};  // alpha: only some kernels write it
    std::size_t cell_of[simplex_block];
    NodeId local[simplex_block][Dim + 1];
    auto c = static_cast<std::size_t>(first);
    const auto stop = static_cast<std::size_t>(end);
    while (c < stop) {
        // Up to a block of simplices: first their nodes' local ids (independent
        // loads from local_id, many in flight), then their points.
        std::size_t count = 0;
        for (; c < stop && count < simplex_block; ++c) {
            if (cells.types[c] != simplex) {
                other(c);
                continue;
            }
            const NodeId* v = cells.nodes.data() + cells.offsets[c];
            for (int k = 0; k <= Dim; ++k) local[count][k] = g.local_id[static_cast<std::size_t>(v[k])];
            cell_of[count++] = c;
        }
        for (std::size_t i = 0; i < count; ++i) {
            const double* x0 = p + Dim * static_cast<std::size_t>(local[i][0]);
            for (int k = 1; k <= Dim; ++k) {
                const double* xk = p + Dim * static_cast<std::size_t>(local[i][k]);
                for (int j = 0; j < Dim; ++j) block.e[(k - 1) * Dim + j][i] = xk[j] - x0[j];
            }
            block.sign[i] = orientations.empty() || orientations[cell_of[i]] >= 0 ? 1.0 : -1.0;
        }
        if (count == 0) continue;
        kernel(block, count, value, alpha);
        for (std::size_t i = 0; i < count; ++i) done(cell_of[i], value[i], alpha[i]);
    }
}

/// The pass over every cell of `mesh` (pass_cells), in fixed blocks over the threads.
template <class Kernel3, class Kernel2, class Done, class Other>
void layout_pass(const QualityLayout& g, const Mesh& mesh, const double* p, std::span<const std::int8_t> orientations,
                 Kernel3&& kernel3, Kernel2&& kernel2, Done&& done, Other&& other) {
    const auto n = static_cast<std::int64_t>(mesh.cells.size());
    parallel_for(
        (n + pass_block - 1) / pass_block,
        [&](std::int64_t b) {
            const std::int64_t first = b * pass_block, end = std::min(n, first + pass_block);
            if (g.dim == 3)
                pass_cells<3>(g, mesh.cells, p, orientations, first, end, kernel3, done, other);
            else
                pass_cells<2>(g, mesh.cells, p, orientations, first, end, kernel2, done, other);
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
        layout, mesh, local.get(), orientations,
        [](const quality_detail::SimplexBlock& b, std::size_t n, double* q, double*) {
            quality_detail::tetrahedron_qualities(b, n, q);
        },
        [](const quality_detail::SimplexBlock& b, std::size_t n, double* q, double*) {
            quality_detail::triangle_qualities(b, n, q);
        },
        [&](std::size_t c, double q, double) { quality[c] = q; },
        [&](std::size_t c) {
            quality[c] = element_shape_quality(mesh.cells, c, mesh.dim, points, orientations[c]);
        });
    return quality;
}

std::vector<std::int8_t> cell_orientations(const QualityLayout& layout, const Mesh& mesh) {
    const std::unique_ptr<double[]> local = layout.fits(mesh) ? local_points(layout, mesh.points) : nullptr;
    if (!local) return cell_orientations(mesh);
    std::vector<std::int8_t> orientation(mesh.cells.size());
    layout_pass(
        layout, mesh, local.get(), {},
        [](const quality_detail::SimplexBlock& b, std::size_t n, double* alpha, double*) {
            quality_detail::tetrahedron_alphas(b, n, alpha);
        },
        [](const quality_detail::SimplexBlock& b, std::size_t n, double* alpha, double*) {
            quality_detail::triangle_alphas(b, n, alpha);
        },
        [&](std::size_t c, double alpha, double) { orientation[c] = static_cast<std::int8_t>(alpha < 0 ? -1 : 1); },
        [&](std::size_t c) {
            orientation[c] = static_cast<std::int8_t>(element_orientation(mesh.cells, c, mesh.dim, mesh.points));
        });
    return orientation;
}

std::vector<double> original_qualities(const QualityLayout& layout, const Mesh& mesh, std::vector<std::int8_t>& own,
                                       std::vector<std::int8_t>& orientation) {
    const std::unique_ptr<double[]> local = layout.fits(mesh) ? local_points(layout, mesh.points) : nullptr;
    if (!local) {
        own = cell_orientations(mesh);
        orientation = dominant_orientations(mesh, own);
        return cell_qualities(mesh, mesh.points, orientation);
    }
    // One pass: each simplex's own orientation and its quality against +1;
    // the other cells' own orientations.
    const std::size_t n = mesh.cells.size();
    own.resize(n);
    std::vector<double> quality(n);
    layout_pass(
        layout, mesh, local.get(), {}, quality_detail::tetrahedron_qualities_and_alphas,
        quality_detail::triangle_qualities_and_alphas,
        [&](std::size_t c, double q, double alpha) {
            quality[c] = q;
            own[c] = static_cast<std::int8_t>(alpha < 0 ? -1 : 1);
        },
        [&](std::size_t c) {
            own[c] = static_cast<std::int8_t>(element_orientation(mesh.cells, c, mesh.dim, mesh.points));
        });
    orientation = dominant_orientations(mesh, own);
    // Then against the orientation judged by: a simplex's quality against -1
    // is minus its quality against +1 (0 stays +0); other cells measured again.
    const CellType simplex = mesh.dim == 3 ? CellType::tetrahedron : CellType::triangle;
    const auto cells = static_cast<std::int64_t>(n);
    parallel_for(
        (cells + pass_block - 1) / pass_block,
        [&](std::int64_t b) {
            for (auto c = static_cast<std::size_t>(b * pass_block); c < std::min(n, static_cast<std::size_t>((b + 1) * pass_block)); ++c) {
                if (mesh.cells.types[c] != simplex)
                    quality[c] = element_shape_quality(mesh.cells, c, mesh.dim, mesh.points, orientation[c]);
                else if (orientation[c] < 0 && quality[c] != 0)
                    quality[c] = -quality[c];
            }
        },
        1);
    return quality;
}

}  // namespace dgwarp
