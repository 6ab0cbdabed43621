#pragma once
// Internal: checks shared by prepare_dg_idw and deform_dg_idw.
#include "dgwarp/methods/dg_idw.hpp"

namespace dgwarp {

/// Throws Error when an a is not in [dg_idw_a_min, dg_idw_a_max] or L is not finite and >= 0.
void check_dg_idw_options(const DgIdwOptions& options);

}  // namespace dgwarp
