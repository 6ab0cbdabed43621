#include "dgwarp/core/parallel_for.hpp"

#include <omp.h>

#include <algorithm>

namespace dgwarp {

int num_threads() { return omp_get_max_threads(); }

int available_cores() { return std::max(1, omp_get_num_procs()); }

int max_threads() { return std::max(64, 4 * available_cores()); }

void set_num_threads(int n) { omp_set_num_threads(std::clamp(n, 1, max_threads())); }

}  // namespace dgwarp
