#pragma once
// Random point sets for graph and method tests (deterministic seeds).
#include <cstdint>
#include <random>
#include <vector>

namespace dgwarp::test {

/// n points uniform in [lo, hi]^dim, row-major, from `seed`.
inline std::vector<double> random_points(int dim, int n, std::uint32_t seed, double lo = 0, double hi = 1) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> u(lo, hi);
    std::vector<double> p(static_cast<std::size_t>(n) * dim);
    for (double& x : p) x = u(rng);
    return p;
}

/// The 2^dim corners of [lo, hi]^dim, row-major.
inline std::vector<double> box_corners(int dim, double lo = 0, double hi = 1) {
    std::vector<double> p;
    for (int c = 0; c < (1 << dim); ++c)
        for (int d = 0; d < dim; ++d) p.push_back((c >> d) & 1 ? hi : lo);
    return p;
}

}  // namespace dgwarp::test
