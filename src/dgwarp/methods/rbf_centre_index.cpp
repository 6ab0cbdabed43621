#include "dgwarp/methods/rbf_centre_index.hpp"

#include <nanoflann.hpp>

namespace dgwarp {

namespace {

// nanoflann's dataset interface over row-major points.
struct PointCloud {
    const std::vector<double>* points = nullptr;
    int dim = 3;

    std::size_t kdtree_get_point_count() const { return points->size() / static_cast<std::size_t>(dim); }
    double kdtree_get_pt(std::size_t i, std::size_t d) const { return (*points)[i * dim + d]; }
    template <class Box>
    bool kdtree_get_bbox(Box&) const {
        return false;
    }
};

using Tree = nanoflann::KDTreeSingleIndexAdaptor<nanoflann::L2_Simple_Adaptor<double, PointCloud>, PointCloud, -1,
                                                 std::uint32_t>;

// Collects indices only (nanoflann's RadiusResultSet stores distances too).
struct IndexCollector {
    double radius2;
    std::vector<std::uint32_t>* found;

    bool full() const { return true; }
    double worstDist() const { return radius2; }
    bool addPoint(double dist, std::uint32_t index) {
        if (dist < radius2) found->push_back(index);
        return true;
    }
};

}  // namespace

struct RbfCentreIndex {
    std::vector<double> points;
    PointCloud cloud;
    Tree tree;

    RbfCentreIndex(int dim, std::span<const double> p)
        : points(p.begin(), p.end()), cloud{&points, dim}, tree(dim, cloud, nanoflann::KDTreeSingleIndexAdaptorParams(16)) {}
};

std::shared_ptr<const RbfCentreIndex> build_centre_index(int dim, std::span<const double> points) {
    return std::make_shared<const RbfCentreIndex>(dim, points);
}

void centres_within(const RbfCentreIndex& index, const double* x, double radius, std::vector<std::uint32_t>& found) {
    found.clear();
    IndexCollector collector{radius * radius, &found};
    index.tree.findNeighbors(collector, x, nanoflann::SearchParams(32, 0, false));
}

std::size_t index_bytes(const RbfCentreIndex& index) {
    // Points, the tree's index permutation, and about one node per 8 points (leaves of up to 16).
    const std::size_t n = index.cloud.kdtree_get_point_count();
    return index.points.capacity() * sizeof(double) + n * sizeof(std::uint32_t) + n / 8 * 64;
}

}  // namespace dgwarp
