#include "dgwarp/graph/simplex_orientation.hpp"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <algorithm>
#include <cassert>
#include <cmath>
#include <limits>

#include "dgwarp/core/parallel_for.hpp"

namespace dgwarp {

namespace {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;

// Whether the simplex with corners c[0..dim] of `x` is flat to round-off (see the header).
bool flat_to_round_off(int dim, const std::int32_t* c, const double* x) {
    double e[3][3] = {}, longest = 0, largest = 0;
    for (int k = 0; k <= dim; ++k)
        for (int d = 0; d < dim; ++d) largest = std::max(largest, std::abs(x[c[k] * dim + d]));
    for (int k = 1; k <= dim; ++k) {
        double sq = 0;
        for (int d = 0; d < dim; ++d) {
            e[k - 1][d] = x[c[k] * dim + d] - x[c[0] * dim + d];
            sq += e[k - 1][d] * e[k - 1][d];
        }
        longest = std::max(longest, std::sqrt(sq));
    }
    // Edges between non-zero corners can be longer than those from corner 0 by at most 2x.
    longest *= 2;
    const double det = dim == 2 ? e[0][0] * e[1][1] - e[0][1] * e[1][0]
                                : e[0][0] * (e[1][1] * e[2][2] - e[1][2] * e[2][1]) -
                                      e[0][1] * (e[1][0] * e[2][2] - e[1][2] * e[2][0]) +
                                      e[0][2] * (e[1][0] * e[2][1] - e[1][1] * e[2][0]);
    const double u = std::numeric_limits<double>::epsilon() / 2;
    const double tau = 16 * dim * u * (largest + longest) * (dim == 2 ? longest : longest * longest);
    return std::abs(det) <= tau;
}

CGAL::Orientation orientation(int dim, const std::int32_t* c, const double* x) {
    if (dim == 2) {
        auto p = [&](int k) { return K::Point_2(x[2 * c[k]], x[2 * c[k] + 1]); };
        return CGAL::orientation(p(0), p(1), p(2));
    }
    auto p = [&](int k) { return K::Point_3(x[3 * c[k]], x[3 * c[k] + 1], x[3 * c[k] + 2]); };
    return CGAL::orientation(p(0), p(1), p(2), p(3));
}

}  // namespace

std::vector<std::uint8_t> invalid_moved_simplices(int dim, std::span<const std::int32_t> simplices,
                                                  std::span<const double> from, std::span<const double> to) {
    assert(dim == 2 || dim == 3);
    assert(from.size() == to.size());
    const std::size_t corners = static_cast<std::size_t>(dim) + 1;
    const auto n = static_cast<std::int64_t>(simplices.size() / corners);
    std::vector<std::uint8_t> bad(static_cast<std::size_t>(n), 0);
    parallel_for(n, [&](std::int64_t s) {
        const std::int32_t* c = simplices.data() + static_cast<std::size_t>(s) * corners;
        if (orientation(dim, c, to.data()) == CGAL::POSITIVE) return;
        bad[static_cast<std::size_t>(s)] = !(flat_to_round_off(dim, c, from.data()) && flat_to_round_off(dim, c, to.data()));
    });
    return bad;
}

std::int64_t count_invalid_moved_simplices(int dim, std::span<const std::int32_t> simplices,
                                           std::span<const double> from, std::span<const double> to) {
    const std::vector<std::uint8_t> bad = invalid_moved_simplices(dim, simplices, from, to);
    return std::count(bad.begin(), bad.end(), std::uint8_t{1});
}

}  // namespace dgwarp
