#pragma once
// Internal to RBF: a k-d tree (nanoflann 1.4) over a set of centres, for the
// neighbours within the support radius.
#include <cstdint>
#include <memory>
#include <span>
#include <vector>

#include "dgwarp/methods/rbf.hpp"

namespace dgwarp {

/// Builds the tree over `points` (n × dim, row-major; copied: the tree owns them).
std::shared_ptr<const RbfCentreIndex> build_centre_index(int dim, std::span<const double> points);

/// Indices of the centres strictly closer than `radius` to `x` (dim
/// coordinates), appended to `found` (cleared first) in the tree's traversal
/// order, which depends only on the tree and x.
void centres_within(const RbfCentreIndex& index, const double* x, double radius, std::vector<std::uint32_t>& found);

/// Bytes held by the index (points and tree nodes, estimated).
std::size_t index_bytes(const RbfCentreIndex& index);

}  // namespace dgwarp
