// py_mpi.hpp: the distributed plans through mpi4py.
#include "py_mpi.hpp"

#include <pybind11/numpy.h>

#include <string>

#if defined(DGWARP_PYTHON_MPI)
#include <mpi4py/mpi4py.h>

#include "dgwarp/mpi/agreement.hpp"
#include "dgwarp/mpi/distributed_plan.hpp"
#include "dgwarp/mpi/distributed_plan_file.hpp"
#endif

namespace py = pybind11;

namespace dgwarp::python {

#if defined(DGWARP_PYTHON_MPI)

struct DistributedHolder {
    mpi::DistributedPlan plan;
};

bool has_mpi() { return true; }

namespace {

/// The MPI communicator of an mpi4py.MPI.Comm (TypeError otherwise).
MPI_Comm communicator(py::handle comm) {
    if (import_mpi4py() < 0) throw py::error_already_set();
    if (!PyObject_TypeCheck(comm.ptr(), &PyMPIComm_Type))
        throw py::type_error("comm must be an mpi4py.MPI.Comm (e.g. MPI.COMM_WORLD), got " +
                             py::str(py::type::of(comm)).cast<std::string>());
    const MPI_Comm* c = PyMPIComm_Get(comm.ptr());
    if (c == nullptr) throw py::error_already_set();
    return *c;
}

/// global_ids as int64, one per local node (TypeError / ValueError otherwise).
py::array_t<std::int64_t> ids_arg(py::handle global_ids, int dim, std::span<const double> points, const char* function) {
    if (global_ids.is_none())
        throw py::type_error(std::string(function) + "(comm=...) needs global_ids: each local node's id in the whole mesh");
    const auto ids = py::array_t<std::int64_t, py::array::c_style | py::array::forcecast>::ensure(global_ids);
    if (!ids || ids.ndim() != 1)
        throw py::value_error("global_ids must be a 1D integer array, one id per local node");
    if (static_cast<std::size_t>(ids.size()) * static_cast<std::size_t>(dim) != points.size())
        throw py::value_error("global_ids has " + std::to_string(ids.size()) + " ids for " +
                              std::to_string(points.size() / static_cast<std::size_t>(dim)) + " local nodes");
    return ids;
}

}  // namespace

void collectively_on(py::handle comm, const std::function<void()>& check) {
    mpi::collectively(communicator(comm), check);
}

std::shared_ptr<const DistributedHolder> prepare_distributed_plan(py::handle comm, Method method, int dim,
                                                                  std::span<const double> points,
                                                                  py::handle global_ids, const BoundarySet& boundary,
                                                                  const MethodOptions& options) {
    const MPI_Comm c = communicator(comm);
    const auto ids = ids_arg(global_ids, dim, points, "prepare");
    auto holder = std::make_shared<DistributedHolder>();
    const std::span<const std::int64_t> id_span(ids.data(), static_cast<std::size_t>(ids.size()));
    py::gil_scoped_release release;
    holder->plan = mpi::prepare_distributed(c, method, dim, points, id_span, boundary, options);
    return holder;
}

std::shared_ptr<const DistributedHolder> load_distributed_plan_file(py::handle comm, const std::filesystem::path& path,
                                                                    int dim, std::span<const double> points,
                                                                    py::handle global_ids,
                                                                    const BoundarySet& boundary) {
    const MPI_Comm c = communicator(comm);
    const auto ids = ids_arg(global_ids, dim, points, "load_plan");
    auto holder = std::make_shared<DistributedHolder>();
    const std::span<const std::int64_t> id_span(ids.data(), static_cast<std::size_t>(ids.size()));
    py::gil_scoped_release release;
    holder->plan = mpi::load_distributed_plan(c, path, points, id_span, boundary);
    return holder;
}

void save_distributed_plan_file(const DistributedHolder& plan, const std::filesystem::path& path) {
    py::gil_scoped_release release;
    mpi::save_distributed_plan(path, plan.plan);
}

Method distributed_method(const DistributedHolder& plan) { return plan.plan.method; }

StepReport deform_distributed_plan(const DistributedHolder& plan, std::span<const double> points,
                                   const BoundaryMotion& motion, std::span<double> out) {
    return mpi::deform_distributed(plan.plan, points, motion, out);
}

const Plan& distributed_method_plan(const DistributedHolder& plan) { return plan.plan.plan; }

std::size_t distributed_bytes(const DistributedHolder& plan) { return mpi::distributed_plan_bytes(plan.plan); }

#else

struct DistributedHolder {
    Plan plan;
};

bool has_mpi() { return false; }

void collectively_on(py::handle, const std::function<void()>& check) { check(); }

std::shared_ptr<const DistributedHolder> prepare_distributed_plan(py::handle, Method, int, std::span<const double>,
                                                                  py::handle, const BoundarySet&,
                                                                  const MethodOptions&) {
    throw py::value_error("prepare(comm=...): this dgwarp was built without MPI (CMake did not find Open MPI "
                          "and mpi4py: install libopenmpi-dev and python3-mpi4py, then build again)");
}

StepReport deform_distributed_plan(const DistributedHolder&, std::span<const double>, const BoundaryMotion&,
                                   std::span<double>) {
    return {};
}

std::shared_ptr<const DistributedHolder> load_distributed_plan_file(py::handle, const std::filesystem::path&, int,
                                                                    std::span<const double>, py::handle,
                                                                    const BoundarySet&) {
    return prepare_distributed_plan(py::none(), Method::dg_idw, 2, {}, py::none(), {}, {});  // raises
}

void save_distributed_plan_file(const DistributedHolder&, const std::filesystem::path&) {}

Method distributed_method(const DistributedHolder&) { return Method::dg_idw; }

const Plan& distributed_method_plan(const DistributedHolder& plan) { return plan.plan; }

std::size_t distributed_bytes(const DistributedHolder&) { return 0; }

#endif

}  // namespace dgwarp::python
