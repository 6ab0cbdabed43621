#pragma once
// The displacement a job's motion gives its boundary nodes in one frame, as
// the file's mesh numbers them: for another solver to apply the same
// boundary motion (`dgwarp motion-field`: CSV, or OpenFOAM's
// pointDisplacement).
#include <cstddef>
#include <vector>

#include "dgwarp/core/warning.hpp"
#include "dgwarp/job/job_inputs.hpp"

namespace dgwarp {

struct BoundaryDisplacement {
    /// Per node of output_mesh(in), num_points × dim: new position minus old
    /// (zero for the fixed boundary nodes and every volume node).
    std::vector<double> displacement;
    /// The boundary nodes in output_mesh(in)'s numbering (a 2D case's twins
    /// in both planes), with which of them move.
    BoundarySet boundary;
    std::vector<Warning> warnings;  // the frame's (resolve_frame)
};

/// Frame `frame` of in.spec on in.boundary (resolve_frame): every boundary
/// node's displacement, sliding nodes by their first pass (run/slide_pass.hpp,
/// as every method moves them), a 2D case's lifted to its 3D nodes. Throws
/// as resolve_frame does.
BoundaryDisplacement boundary_displacement(const JobInputs& in, std::size_t frame);

}  // namespace dgwarp
