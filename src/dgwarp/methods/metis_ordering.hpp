#pragma once
// A fill-reducing ordering for Eigen's SimplicialLDLT: METIS's nested
// dissection (METIS_NodeND with its default, fixed seed: the same permutation
// on every run and process), AMD when METIS declines (fewer than 3 unknowns,
// or an error). Eigen's own MetisOrdering prints to stderr and leaves no
// permutation on an error. Used by DG-harmonic's coarse Laplacian and the
// laplacian reference method; include only in sources (it pulls in metis.h
// and Eigen).
#include <metis.h>

#include <Eigen/OrderingMethods>
#include <vector>

namespace dgwarp {

struct MetisOrAmdOrdering {
    /// `a`: the full symmetric pattern; `pinv` gets the permutation.
    template <class MatrixType>
    void operator()(const MatrixType& a, Eigen::PermutationMatrix<Eigen::Dynamic, Eigen::Dynamic, int>& pinv) {
        idx_t n = static_cast<idx_t>(a.cols());
        std::vector<idx_t> start{0}, adjacent;
        start.reserve(static_cast<std::size_t>(n) + 1);
        adjacent.reserve(static_cast<std::size_t>(a.nonZeros()));
        for (idx_t j = 0; j < n; ++j) {
            for (typename MatrixType::InnerIterator it(a, j); it; ++it)
                if (it.index() != j) adjacent.push_back(static_cast<idx_t>(it.index()));
            start.push_back(static_cast<idx_t>(adjacent.size()));
        }
        std::vector<idx_t> perm(static_cast<std::size_t>(n)), iperm(static_cast<std::size_t>(n));
        if (n < 3 || METIS_NodeND(&n, start.data(), adjacent.data(), nullptr, nullptr, perm.data(), iperm.data()) !=
                         METIS_OK) {
            Eigen::AMDOrdering<int>()(a, pinv);
            return;
        }
        // As Eigen's MetisOrdering does: entry iperm[j] (j's new position) is j.
        pinv.resize(n);
        for (idx_t j = 0; j < n; ++j) pinv.indices()(iperm[j]) = static_cast<int>(j);
    }
};

}  // namespace dgwarp
