#pragma once
// dgwarp.prepare(..., comm=..., global_ids=...) (docs/PYTHON.md, "MPI"): a
// plan over this process's part of a partitioned mesh, prepared and stepped
// collectively with mpi4py's communicator, as the C++ distributed API
// (dgwarp/mpi/distributed_plan.hpp) does it: bit-identical to one process.
// Built when CMake found MPI and mpi4py; otherwise comm= raises an Error.
#include <pybind11/pybind11.h>

#include <cstdint>
#include <filesystem>
#include <functional>
#include <memory>
#include <span>

#include "dgwarp/methods/method.hpp"

namespace dgwarp::python {

/// A process's distributed plan (the C++ DistributedPlan), opaque here.
struct DistributedHolder;

/// Whether the module was built with MPI and mpi4py.
bool has_mpi();

/// Runs `check` on this process, then agrees over `comm` (an mpi4py.MPI.Comm;
/// mpi/agreement.hpp): when it threw on any process, every process throws
/// (the others an error naming that process), so that none is left waiting
/// in the collective call that follows. Without MPI: `check`.
void collectively_on(pybind11::handle comm, const std::function<void()>& check);

/// Prepares `method` collectively over `comm` (an mpi4py.MPI.Comm) for this
/// process's nodes: `points` (num_local × dim), `global_ids` (one integer
/// per local node, its id in the whole mesh), `boundary` (its boundary nodes,
/// classified from its markers). Releases the GIL while it waits for the others.
std::shared_ptr<const DistributedHolder> prepare_distributed_plan(pybind11::handle comm, Method method, int dim,
                                                                  std::span<const double> points,
                                                                  pybind11::handle global_ids,
                                                                  const BoundarySet& boundary,
                                                                  const MethodOptions& options);

/// The same from a file saved by save_distributed_plan_file (collective;
/// load_distributed_plan's checks: the same partition and inputs).
std::shared_ptr<const DistributedHolder> load_distributed_plan_file(pybind11::handle comm,
                                                                    const std::filesystem::path& path, int dim,
                                                                    std::span<const double> points,
                                                                    pybind11::handle global_ids,
                                                                    const BoundarySet& boundary);

/// Writes every process's part into one file (collective; releases the GIL).
void save_distributed_plan_file(const DistributedHolder& plan, const std::filesystem::path& path);

/// The method a distributed plan runs.
Method distributed_method(const DistributedHolder& plan);

/// One collective step (call without the GIL).
StepReport deform_distributed_plan(const DistributedHolder& plan, std::span<const double> points,
                                   const BoundaryMotion& motion, std::span<double> out);

/// The method's plan over this process's working nodes.
const Plan& distributed_method_plan(const DistributedHolder& plan);

/// Bytes this process holds for the plan.
std::size_t distributed_bytes(const DistributedHolder& plan);

}  // namespace dgwarp::python
