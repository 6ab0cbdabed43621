#pragma once
// Order statistics of a sample, for the benchmark's summaries.
#include <vector>

namespace dgwarp {

/// The median of `v` (the mean of the two middle values for an even count); NaN when empty.
double median(std::vector<double> v);

/// The p-th percentile of `v` (p in [0, 100]) by the nearest-rank method; NaN when empty.
double percentile(std::vector<double> v, double p);

}  // namespace dgwarp
