#pragma once
// dgwarp.Plan: a method's plan for one mesh and one classification of its
// boundary markers (moving / static), prepared once and used for every step.
#include <pybind11/pybind11.h>

#include <cstdint>
#include <memory>
#include <mutex>
#include <optional>
#include <vector>

#include "dgwarp/methods/method.hpp"
#include "dgwarp/motion/resolve_motion.hpp"
#include "dgwarp/run/original_cells.hpp"
#include "dgwarp/run/slide_pass.hpp"
#include "py_mesh.hpp"
#include "py_mpi.hpp"

namespace dgwarp::python {

struct PyPlan {
    MeshPtr mesh;                // the mesh it was prepared for (immutable, shared)
    ResolvedBoundary boundary;   // markers moving / static, boundary nodes, what resolve_frame reuses
    SharedNodeRule shared_nodes = SharedNodeRule::moving_wins;
    double shared_tolerance = 0;  // as given to the classification (0: the default)
    MethodOptions options;       // as used (a loaded plan's own)
    Plan plan;                   // unused (default) when distributed
    /// With sliding or cyclic markers: their first pass (run/slide_pass.hpp),
    /// which every step runs before the plan's.
    std::optional<SlidePass> slide;
    MotionSpec classified_by;    // the motion (or the marker lists made one) the boundary was classified by
    /// A plan over this process's part, prepared with comm= (py_mpi.hpp),
    /// and the mpi4py communicator it uses (kept alive with the plan).
    std::shared_ptr<const DistributedHolder> distributed;
    pybind11::object comm;

    /// The original cells a step is repaired and judged against
    /// (measure_original, as `dgwarp deform`), computed on first use, once
    /// (thread-safe; call without the GIL).
    const OriginalCells& original() const;

private:
    mutable std::once_flag original_once_;
    mutable OriginalCells original_;
};

/// The method's plan a step of `p` runs: this process's part of a
/// distributed plan, else p.plan.
inline const Plan& plan_of(const PyPlan& p) { return p.distributed ? distributed_method_plan(*p.distributed) : p.plan; }

}  // namespace dgwarp::python
