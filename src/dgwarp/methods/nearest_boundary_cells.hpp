#pragma once
// Approximate nearest boundary nodes for every volume node, cheaply: the
// coarse-point selection of DG-harmonic (coarse_points.hpp) needs each volume
// node's wall distance within a factor of about 1.5 only, and one k-d tree
// query per node (0.3-0.5 µs each) was half of DG-harmonic's prepare.
//
// A 2^dim-tree over the boundary nodes' bounding cube, refined lazily along
// the paths the queries take. Every cell holds the (approximate) 4 nearest
// boundary nodes of its centre (one k-d tree query per cell) and stops
// refining once its half-diagonal r is at most half the coarse spacing its
// centre wants, max(wall_spacing h_j, growth d) for its nearest node j at
// distance d. A query point takes the nearest of its leaf's nodes: the
// answer's distance is exact for that node (an upper bound of the wall
// distance; on the 257k-node wing-body the coarse wants it gives average
// those of one k-d tree query per node, ratio 1.0000, where the leaf's
// nearest node alone gave 1.0105), and the leaf also gives a lower
// bound, d / 1.2248 - r (the centre's d is within a factor sqrt(1.5) of its
// true wall distance). The tree depends on the boundary nodes and the
// spacing only, so a point's answer depends on its coordinates only, whatever
// the other queries and their order (the MPI path's processes agree with one
// process).
#include <cstdint>
#include <span>
#include <vector>

#include "dgwarp/graph/nearest_node.hpp"
#include "dgwarp/mesh/mesh.hpp"

namespace dgwarp {

struct CoarseSpacing;

class NearestBoundaryCells {
public:
    /// `tree`: over the boundary nodes (kept by reference); `h`: per boundary
    /// node, its spacing (NearestNode::spacing). Not thread-safe: queries refine
    /// the tree.
    NearestBoundaryCells(int dim, std::span<const double> points, std::span<const NodeId> boundary_nodes,
                         const NearestNode& tree, std::span<const double> h, const CoarseSpacing& spacing);

    struct Answer {
        std::int64_t index = -1;  // position in boundary_nodes; -1: x is outside the cube (ask the tree)
        double distance = 0;      // from x to that node
        double lower_bound = 0;   // no boundary node is nearer to x than this
    };
    Answer find(const double* x);

    std::size_t num_cells() const { return cells_.size(); }

private:
    static constexpr int candidates = 4;
    struct Cell {
        double node_xyz[candidates][3];  // its boundary nodes' coordinates
        double lower_bound;              // of the wall distance anywhere in the cell
        std::int32_t index[candidates];  // its boundary nodes (positions in boundary_nodes), nearest first
        std::int32_t count;              // how many
        std::int32_t children;           // first of its 2^dim children; -1: none yet
        bool leaf;
    };
    void add_cell(const double* corner, double size);

    int dim_;
    std::span<const double> points_;
    std::span<const NodeId> boundary_nodes_;
    const NearestNode& tree_;
    std::span<const double> h_;
    double wall_spacing_, growth_;
    double lo_[3] = {}, size_ = 0;  // the root cube; size 0: no cube (every query is outside)
    std::vector<Cell> cells_;
    // The last leaf found: consecutive queries along a Morton curve mostly fall in it.
    std::int32_t last_ = -1;
    double last_lo_[3] = {}, last_hi_[3] = {};  // its box, half-open
};

}  // namespace dgwarp
