#pragma once
// A mesh's cells laid out for the quality pass: what `dgwarp deform`
// measures around every frame (Knupp's metric of every cell) at the speed of
// a pass over memory. Built once per mesh (the run layer's OriginalCells).
//
// The layout numbers the nodes its own way, along a Morton curve: local node
// k is mesh node local_order[k], and each pass first copies the points into
// that order (one pass over the nodes), so that neighbouring cells read
// neighbouring points whatever the mesh's node numbering. The simplices
// (triangles of a 2D mesh, tetrahedra) keep the cells' order (so the
// orientations are read and the qualities written in order) with local node
// ids, and are measured in blocks of 256 by a vectorised kernel
// (simplex_kernel.hpp). Other cells go through cell_shape_quality, by index.
// Every value is cell_shape_quality's to the bit
// (tests/quality/quality_layout_test.cpp). On the 865k-node sphere (5.3M
// tetrahedra in Gmsh's order) grouping the simplices by their first node's
// local id instead (as DG-harmonic's guard does) measured slower: the
// orientations read and the qualities written by cell id then miss the cache.
#include <cstdint>
#include <memory>
#include <span>
#include <vector>

#include "dgwarp/mesh/mesh.hpp"

namespace dgwarp {

struct QualityLayout {
    int dim = 0;
    std::size_t num_points = 0, num_cells = 0;
    std::vector<NodeId> local_order;          // num_points: Morton order of the nodes
    std::vector<NodeId> simplex_nodes;        // (dim + 1) per simplex, local node ids
    std::vector<std::uint32_t> simplex_cell;  // per simplex, its cell
    std::vector<std::uint32_t> other_cells;   // the other cells, ascending

    /// Whether the layout holds `mesh`'s cells (a mesh of 2^32 cells or more gets none).
    bool fits(const Mesh& mesh) const {
        return dim == mesh.dim && num_points == mesh.num_points() && num_cells == mesh.cells.size() &&
               simplex_cell.size() + other_cells.size() == num_cells;
    }
};

/// The layout of `mesh`'s cells (cells and points as checked by Mesh's own
/// validation: node ids in range). Threaded. A mesh with 2^32 cells or more
/// gets an empty layout (fits() false: the passes take the cells one by one).
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
