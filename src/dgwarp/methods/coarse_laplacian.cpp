// coarse_laplacian.hpp: DG-harmonic's coarse Laplacians, factorised with a pivot check.
#include "dgwarp/methods/coarse_laplacian.hpp"

#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>
#include <algorithm>
#include <cmath>
#include <string>

#include "dgwarp/core/error.hpp"
#include "dgwarp/methods/metis_ordering.hpp"

namespace dgwarp {

bool pivots_positive(std::span<const double> d, double relative) {
    double largest = 0;
    for (double v : d) {
        if (!(v > 0) || !std::isfinite(v)) return false;
        largest = std::max(largest, v);
    }
    return std::all_of(d.begin(), d.end(), [&](double v) { return v >= relative * largest; });
}

std::vector<double> floor_weights(std::span<const double> weights, double fraction, std::int64_t* floored) {
    double sum = 0;
    std::int64_t positive = 0;
    for (double w : weights)
        if (w > 0) {
            sum += w;
            ++positive;
        }
    const double floor = fraction * (positive > 0 ? sum / static_cast<double>(positive) : 1.0);
    std::vector<double> out(weights.begin(), weights.end());
    std::int64_t raised = 0;
    for (double& w : out)
        if (!(w >= floor)) {
            w = floor;
            ++raised;
        }
    if (floored) *floored += raised;
    return out;
}

// METIS's nested dissection: on the 826k squeezed sphere's 9,877 unknowns the
// factor has 1.11M non-zeros against AMD's 1.50M, and factorises in half the time.
HarmonicFactors factorise_coarse_laplacian(std::span<const std::pair<std::int32_t, std::int32_t>> edges,
                                           std::span<const double> translation_weight,
                                           std::span<const double> rotation_weight, std::int32_t first_unknown,
                                           std::int32_t num_unknowns, std::int64_t* floored) {
    const std::int32_t nb = first_unknown, n = num_unknowns;
    HarmonicFactors f;
    using Ldlt = Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>, Eigen::Lower, MetisOrAmdOrdering>;
    Ldlt ldlt;
    // B's entries grouped by unknown: the edges (to a boundary vertex) of each.
    std::vector<std::vector<std::size_t>> coupling(static_cast<std::size_t>(n));
    for (std::size_t k = 0; k < edges.size(); ++k)
        if (edges[k].first < nb) coupling[static_cast<std::size_t>(edges[k].second - nb)].push_back(k);
    std::vector<std::size_t> coupling_edge;
    for (const auto& row : coupling) {
        for (std::size_t k : row) {
            f.coupling_vertex.push_back(edges[k].first);
            coupling_edge.push_back(k);
        }
        f.coupling_start.push_back(static_cast<std::int64_t>(f.coupling_vertex.size()));
    }
    bool analysed = false;
    // Assembles the unknowns' block with `weight` and factorises it; false on a bad pivot.
    const auto factor_system = [&](std::span<const double> weight, HarmonicFactors::System& sys) {
        std::vector<Eigen::Triplet<double, int>> a;
        a.reserve(edges.size() + static_cast<std::size_t>(n));
        std::vector<double> diagonal(static_cast<std::size_t>(n), 0.0);
        for (std::size_t k = 0; k < edges.size(); ++k) {
            const auto [u, v] = edges[k];
            const double w = weight[k];
            diagonal[static_cast<std::size_t>(v - nb)] += w;
            if (u >= nb) {
                diagonal[static_cast<std::size_t>(u - nb)] += w;
                a.emplace_back(v - nb, u - nb, -w);  // lower triangle; zeros kept, so both share one pattern
            }
        }
        for (std::int32_t i = 0; i < n; ++i) a.emplace_back(i, i, diagonal[static_cast<std::size_t>(i)]);
        Eigen::SparseMatrix<double> m(n, n);
        m.setFromTriplets(a.begin(), a.end());
        if (!analysed) {
            ldlt.analyzePattern(m);
            analysed = true;
        }
        ldlt.factorize(m);
        if (ldlt.info() != Eigen::Success) return false;
        const Eigen::VectorXd d = ldlt.vectorD();  // a copy: vectorD() returns by value
        if (!pivots_positive(std::span<const double>(d.data(), static_cast<std::size_t>(d.size())))) return false;
        const Eigen::SparseMatrix<double>& l = ldlt.matrixL().nestedExpression();
        if (f.perm.empty()) {
            const auto& p = ldlt.permutationP().indices();
            f.perm.assign(p.data(), p.data() + p.size());
            f.l_start.assign(l.outerIndexPtr(), l.outerIndexPtr() + n + 1);
            f.l_row.assign(l.innerIndexPtr(), l.innerIndexPtr() + l.nonZeros());
        }
        sys.l_value.assign(l.valuePtr(), l.valuePtr() + l.nonZeros());
        sys.d.assign(d.data(), d.data() + n);
        sys.coupling_weight.clear();
        for (std::size_t k : coupling_edge) sys.coupling_weight.push_back(weight[k]);
        return true;
    };
    f.shared = std::equal(translation_weight.begin(), translation_weight.end(), rotation_weight.begin(),
                          rotation_weight.end());
    for (auto [weight, sys] : {std::pair{translation_weight, &f.translation}, std::pair{rotation_weight, &f.rotation}}) {
        if (f.shared && sys == &f.rotation) break;
        if (factor_system(weight, *sys)) continue;
        // A zero pivot: an unknown whose edges all lost their weight (negative
        // P1 sums set to 0). Every weight at least a millionth of the mean.
        const std::vector<double> raised = floor_weights(weight, 1e-6, floored);
        if (!factor_system(raised, *sys))
            throw Error("DG-harmonic: the coarse Laplacian could not be factorised (" + std::to_string(n) +
                        " unknowns), even with every edge weight at least 1e-6 of the mean");
    }
    return f;
}

}  // namespace dgwarp
