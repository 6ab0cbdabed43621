#include "dgwarp/methods/nearest_boundary_cells.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "dgwarp/methods/coarse_points.hpp"

namespace dgwarp {

namespace {

// The k-d tree's relative error for a cell's centre: the node found is at
// most sqrt(1 + e) times farther than the nearest (nanoflann's error bounds
// squared distances).
constexpr double centre_error = 0.5;
// A cell this many halvings below the root is a leaf whatever its spacing
// (boundary nodes at one point have spacing 0).
constexpr int max_depth = 40;

}  // namespace

NearestBoundaryCells::NearestBoundaryCells(int dim, std::span<const double> points,
                                           std::span<const NodeId> boundary_nodes, const NearestNode& tree,
                                           std::span<const double> h, const CoarseSpacing& spacing)
    : dim_(dim), points_(points), boundary_nodes_(boundary_nodes), tree_(tree), h_(h),
      wall_spacing_(spacing.wall_spacing), growth_(spacing.growth) {
    if (boundary_nodes.empty()) return;
    const BoundingBox box = bounding_box(dim, points, boundary_nodes);
    for (int d = 0; d < dim; ++d) {
        lo_[d] = box.min[d];
        size_ = std::max(size_, box.max[d] - box.min[d]);
    }
    if (!(size_ > 0) || !std::isfinite(size_)) {
        size_ = 0;
        return;
    }
    add_cell(lo_, size_);
}

void NearestBoundaryCells::add_cell(const double* corner, double size) {
    double centre[3] = {};
    for (int d = 0; d < dim_; ++d) centre[d] = corner[d] + 0.5 * size;
    std::int64_t index[candidates];
    double distance[candidates];
    const std::size_t n = tree_.nearest_k(centre, candidates, index, distance, centre_error);
    const double half_diagonal = 0.5 * size * std::sqrt(static_cast<double>(dim_));
    Cell c{};
    c.count = static_cast<std::int32_t>(n);
    for (std::size_t k = 0; k < n; ++k) {
        const auto node = static_cast<std::size_t>(boundary_nodes_[index[k]]);
        for (int d = 0; d < dim_; ++d) c.node_xyz[k][d] = points_[node * dim_ + d];
        c.index[k] = static_cast<std::int32_t>(index[k]);
    }
    // The centre's wall distance is at least distance[0] / sqrt(1 + e); every
    // point of the cell is within half_diagonal of the centre. The factor
    // covers the rounding of both.
    c.lower_bound = distance[0] / std::sqrt(1 + centre_error) * (1 - 1e-12) - half_diagonal;
    c.children = -1;
    c.leaf = half_diagonal <= 0.5 * std::max(wall_spacing_ * h_[index[0]], growth_ * distance[0]);
    cells_.push_back(c);
}

NearestBoundaryCells::Answer NearestBoundaryCells::find(const double* x) {
    if (size_ == 0) return {};
    bool in_last = last_ >= 0;
    for (int d = 0; d < dim_ && in_last; ++d) in_last = x[d] >= last_lo_[d] && x[d] < last_hi_[d];
    if (!in_last) {
        for (int d = 0; d < dim_; ++d)
            if (!(x[d] >= lo_[d] && x[d] <= lo_[d] + size_)) return {};
        std::int32_t cell = 0;
        // The cell's corner and its far side as the halvings computed them (a
        // query in the last leaf is tested against the same numbers).
        double corner[3] = {lo_[0], lo_[1], lo_[2]};
        double far[3] = {lo_[0] + size_, lo_[1] + size_, lo_[2] + size_};
        double size = size_;
        for (int depth = 0; !cells_[cell].leaf && depth < max_depth; ++depth) {
            const double half = 0.5 * size;
            if (cells_[cell].children < 0) {
                const auto first = static_cast<std::int32_t>(cells_.size());
                for (int k = 0; k < (1 << dim_); ++k) {
                    double c[3] = {};
                    for (int d = 0; d < dim_; ++d) c[d] = corner[d] + ((k >> d) & 1) * half;
                    add_cell(c, half);
                }
                cells_[cell].children = first;
            }
            int k = 0;
            for (int d = 0; d < dim_; ++d) {
                const double middle = corner[d] + half;
                if (x[d] >= middle) {
                    k |= 1 << d;
                    corner[d] = middle;
                } else {
                    far[d] = middle;
                }
            }
            cell = cells_[cell].children + k;
            size = half;
        }
        last_ = cell;
        for (int d = 0; d < dim_; ++d) {
            last_lo_[d] = corner[d];
            last_hi_[d] = far[d];
        }
    }
    const Cell& c = cells_[last_];
    Answer a{-1, std::numeric_limits<double>::infinity(), c.lower_bound};
    for (int k = 0; k < c.count; ++k) {
        double d2 = 0;
        for (int d = 0; d < dim_; ++d) d2 += (x[d] - c.node_xyz[k][d]) * (x[d] - c.node_xyz[k][d]);
        const double dk = std::sqrt(d2);
        if (dk < a.distance) a = {c.index[k], dk, c.lower_bound};
    }
    return a;
}

}  // namespace dgwarp
