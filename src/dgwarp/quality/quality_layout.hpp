#pragma once
// A mesh's cells laid out for the quality pass: what `dgwarp deform`
// measures around every frame (Knupp's metric of every cell) at the speed of
// a pass over memory. Built once per mesh (the run layer's OriginalCells).
//
// The layout numbers the nodes its own way, along a Morton curve: local node
// k is mesh node local_order[k], and each pass first copies the points into
// that order (one pass over the nodes), so that neighbouring cells read
// neighbouring points whatever the mesh's node numbering. The pass walks the
// cells in their order (so the orientations are read and the qualities
// written in order), 256 at a time: the simplices among them (triangles of a
// 2D mesh, tetrahedra) have their edge vectors gathered through local_id and
// go to a vectorised kernel (simplex_kernel.hpp); other cells go through
// cell_shape_quality, by index. Every value is cell_shape_quality's to the
// bit (tests/quality/quality_layout_test.cpp). The layout holds two arrays of
// one id per node and nothing per cell. It used to hold a copy of the
// simplices in local ids (106 MB at the 865k-node sphere's 5.3M tetrahedra,
// 83 ms to build): reading the mesh's own cells through local_id (3.5 MB,
// mostly in cache) instead measured 20 ms to build and, on two threads, 100
// ms for the orientations and 140-180 ms for the qualities (before 133 and
// 182 ms; AMD EPYC VM, where most of such a pass is the first touch of the
// result's pages); on one thread 20-30% slower. Grouping the simplices by
// their first node's local id instead (as DG-harmonic's guard does) measured
// slower: the orientations read and the qualities written by cell id then
// miss the cache.
#include <cstdint>
#include <memory>
#include <span>
#include <vector>

#include "dgwarp/mesh/mesh.hpp"

namespace dgwarp {

struct QualityLayout {
    int dim = 0;
    std::size_t num_points = 0, num_cells = 0;
    std::vector<NodeId> local_order;  // num_points: Morton order of the nodes (local node k is node local_order[k])
    std::vector<NodeId> local_id;     // num_points: the inverse (node n is local node local_id[n])

    /// Whether the layout was made for a mesh of `mesh`'s dimension and sizes.
    bool fits(const Mesh& mesh) const {
        return dim == mesh.dim && num_points == mesh.num_points() && num_cells == mesh.cells.size() &&
               local_order.size() == num_points && local_id.size() == num_points;
    }
};

/// The layout of `mesh`'s cells (cells and points as checked by Mesh's own
/// validation: node ids in range). Threaded.
QualityLayout make_quality_layout(const Mesh& mesh);

/// Every point of `points` (num_points × dim) numbered along a Morton curve:
/// local point k is point order[k] (the layout's local_order; DG-harmonic's
/// guard numbers its points the same way).
std::vector<NodeId> morton_numbering(int dim, std::span<const double> points);

/// `points` (num_points × dim) in `order`'s numbering (row k is point
/// order[k]), copied on the threads, the array not initialised first (a pass
/// less over 20 MB at 865k nodes). `largest`, when given, receives the largest
/// |coordinate| copied (NaN passed over, +inf counted).
std::unique_ptr<double[]> points_in_order(std::span<const NodeId> order, int dim, std::span<const double> points,
                                          double* largest = nullptr);

/// Bytes held by a layout's arrays.
std::size_t layout_bytes(const QualityLayout& layout);

}  // namespace dgwarp
