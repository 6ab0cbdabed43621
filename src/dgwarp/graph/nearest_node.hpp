#pragma once
// Nearest-node queries over a set of mesh nodes (a k-d tree, nanoflann
// underneath; it stays inside the .cpp file).
#include <cstdint>
#include <memory>
#include <span>

#include "dgwarp/mesh/mesh.hpp"

namespace dgwarp {

class NearestNode {
public:
    /// A tree over `nodes` (ids into `points`, num_points × dim; their
    /// coordinates are copied). An empty node list is allowed (every query
    /// then finds nothing).
    NearestNode(int dim, std::span<const double> points, std::span<const NodeId> nodes);
    ~NearestNode();
    NearestNode(const NearestNode&) = delete;
    NearestNode& operator=(const NearestNode&) = delete;

    struct Found {
        std::int64_t index = -1;  // position in `nodes`; -1 when the set is empty
        double distance = 0;      // +inf when the set is empty
    };
    /// The nearest node to x (dim coordinates); ties by the tree's order.
    /// With relative_error e > 0, a node at most (1 + e) times farther than
    /// the nearest (faster). Thread-safe.
    Found nearest(const double* x, double relative_error = 0) const;
    /// The k (at most 16) nearest nodes to x, nearest first, as nearest()
    /// finds one; how many were found (fewer when the set is smaller).
    std::size_t nearest_k(const double* x, int k, std::int64_t* index, double* distance,
                          double relative_error = 0) const;
    /// The distance from node `nodes[index]` to the nearest node of the set at
    /// another position (0 when its nearest `k` (at most 16) neighbours all coincide with it).
    double spacing(std::int64_t index, int k = 8) const;

private:
    struct Tree;
    std::unique_ptr<Tree> tree_;
};

}  // namespace dgwarp
