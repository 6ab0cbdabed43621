#include "dgwarp/graph/nearest_node.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <nanoflann.hpp>
#include <vector>

namespace dgwarp {

namespace {

// nanoflann's dataset interface over the nodes' coordinates, copied into one
// contiguous array (leaf scans then read memory in order).
struct NodeCloud {
    std::vector<double> xyz;
    int dim = 3;

    std::size_t kdtree_get_point_count() const { return xyz.size() / static_cast<std::size_t>(dim); }
    double kdtree_get_pt(std::size_t i, std::size_t d) const { return xyz[i * dim + d]; }
    template <class Box>
    bool kdtree_get_bbox(Box&) const {
        return false;
    }
};

using NodeTree = nanoflann::KDTreeSingleIndexAdaptor<nanoflann::L2_Simple_Adaptor<double, NodeCloud>, NodeCloud, -1,
                                                     std::uint32_t>;

}  // namespace

struct NearestNode::Tree {
    NodeCloud cloud;
    NodeTree tree;
    Tree(int dim, std::span<const double> points, std::span<const NodeId> nodes)
        : cloud{gather_points(dim, points, nodes), dim}, tree(dim, cloud, nanoflann::KDTreeSingleIndexAdaptorParams(10)) {}
};

NearestNode::NearestNode(int dim, std::span<const double> points, std::span<const NodeId> nodes) {
    if (!nodes.empty()) tree_ = std::make_unique<Tree>(dim, points, nodes);
}

NearestNode::~NearestNode() = default;

NearestNode::Found NearestNode::nearest(const double* x, double relative_error) const {
    Found f{-1, std::numeric_limits<double>::infinity()};
    nearest_k(x, 1, &f.index, &f.distance, relative_error);
    return f;
}

std::size_t NearestNode::nearest_k(const double* x, int k, std::int64_t* index, double* distance,
                                   double relative_error) const {
    if (!tree_) return 0;
    constexpr int k_max = 16;
    std::uint32_t found[k_max];
    double dist2[k_max];
    nanoflann::KNNResultSet<double, std::uint32_t> result(static_cast<std::size_t>(std::clamp(k, 1, k_max)));
    result.init(found, dist2);
    tree_->tree.findNeighbors(result, x, nanoflann::SearchParams(32, static_cast<float>(relative_error)));
    const std::size_t n = result.size();
    for (std::size_t i = 0; i < n; ++i) {
        index[i] = static_cast<std::int64_t>(found[i]);
        distance[i] = std::sqrt(dist2[i]);
    }
    return n;
}

double NearestNode::spacing(std::int64_t index, int k) const {
    if (!tree_) return 0;
    const NodeCloud& c = tree_->cloud;
    double x[3] = {};
    for (int d = 0; d < c.dim; ++d) x[d] = c.kdtree_get_pt(static_cast<std::size_t>(index), d);
    constexpr int k_max = 16;
    std::uint32_t found[k_max];
    double dist2[k_max];
    // Two neighbours first (the node itself and the nearest other) answer
    // unless the node has a twin; the same value as the k-search (both exact).
    if (k >= 2 && tree_->tree.knnSearch(x, 2, found, dist2) == 2 && dist2[0] == 0 && dist2[1] > 0)
        return std::sqrt(dist2[1]);
    const std::size_t n =
        tree_->tree.knnSearch(x, static_cast<std::size_t>(std::clamp(k, 1, k_max)), found, dist2);
    for (std::size_t i = 0; i < n; ++i)
        if (dist2[i] > 0) return std::sqrt(dist2[i]);
    return 0;
}

}  // namespace dgwarp
