#pragma once
// dgwarp.Plan: a method's plan for one mesh and one classification of its
// boundary markers (moving / static), prepared once and used for every step.
#include <pybind11/pybind11.h>

#include <cstdint>
#include <memory>
#include <mutex>
#include <vector>

#include "dgwarp/methods/method.hpp"
#include "dgwarp/motion/resolve_motion.hpp"
#include "py_mesh.hpp"

namespace dgwarp::python {

/// What the untangle step needs of the original mesh, computed on first use
/// (as the CLI's deform computes it: deform_setup.cpp, read_inputs).
struct RepairReference {
    std::vector<std::int8_t> own_orientation;  // cell_orientations: what untangle keeps
    std::vector<std::int8_t> orientation;      // dominant_orientations: how cells are judged
    std::vector<double> quality;               // the original's per-cell quality
};

struct PyPlan {
    MeshPtr mesh;                // the mesh it was prepared for (immutable, shared)
    ResolvedBoundary boundary;   // markers moving / static, boundary nodes, what resolve_frame reuses
    SharedNodeRule shared_nodes = SharedNodeRule::moving_wins;
    MethodOptions options;       // as used (a loaded plan's own)
    Plan plan;

    /// The repair reference, computed once (thread-safe; call without the GIL).
    const RepairReference& repair_reference() const;

private:
    mutable std::once_flag repair_once_;
    mutable RepairReference repair_;
};

}  // namespace dgwarp::python
