#include "dgwarp/graph/nearest_node.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <nanoflann.hpp>

namespace dgwarp {

namespace {

// nanoflann's dataset interface over a list of node ids into row-major points.
struct NodeCloud {
    std::span<const double> points;
    std::span<const NodeId> nodes;
    int dim = 3;

    std::size_t kdtree_get_point_count() const { return nodes.size(); }
    double kdtree_get_pt(std::size_t i, std::size_t d) const {
        return points[static_cast<std::size_t>(nodes[i]) * dim + d];
    }
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
        : cloud{points, nodes, dim}, tree(dim, cloud, nanoflann::KDTreeSingleIndexAdaptorParams(16)) {}
};

NearestNode::NearestNode(int dim, std::span<const double> points, std::span<const NodeId> nodes) {
    if (!nodes.empty()) tree_ = std::make_unique<Tree>(dim, points, nodes);
}

NearestNode::~NearestNode() = default;

NearestNode::Found NearestNode::nearest(const double* x) const {
    if (!tree_) return {-1, std::numeric_limits<double>::infinity()};
    std::uint32_t j = 0;
    double d2 = 0;
    tree_->tree.knnSearch(x, 1, &j, &d2);
    return {static_cast<std::int64_t>(j), std::sqrt(d2)};
}

double NearestNode::spacing(std::int64_t index, int k) const {
    if (!tree_) return 0;
    const NodeCloud& c = tree_->cloud;
    double x[3] = {};
    for (int d = 0; d < c.dim; ++d) x[d] = c.kdtree_get_pt(static_cast<std::size_t>(index), d);
    constexpr int k_max = 16;
    std::uint32_t found[k_max];
    double dist2[k_max];
    const std::size_t n =
        tree_->tree.knnSearch(x, static_cast<std::size_t>(std::clamp(k, 1, k_max)), found, dist2);
    for (std::size_t i = 0; i < n; ++i)
        if (dist2[i] > 0) return std::sqrt(dist2[i]);
    return 0;
}

}  // namespace dgwarp
