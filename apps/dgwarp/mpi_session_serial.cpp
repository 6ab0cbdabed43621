// mpi_session.hpp without MPI (dgwarp built without Open MPI): one process.
#include <cstdlib>
#include <string>

#include "dgwarp/core/error.hpp"
#include "mpi_session.hpp"

namespace dgwarp::cli {

struct DistributedRun {};

int mpi_start(int&, char**&) {
    // Open MPI's mpirun sets OMPI_COMM_WORLD_SIZE in every process it starts.
    if (const char* size = std::getenv("OMPI_COMM_WORLD_SIZE"); size && std::atoi(size) > 1)
        throw Error("this dgwarp was built without MPI, but mpirun started " + std::string(size) +
                    " copies of it: install libopenmpi-dev (scripts/install-deps.sh) and build again, or run "
                    "one dgwarp without mpirun");
    return 1;
}
int mpi_rank() { return 0; }
int mpi_processes() { return 1; }
int mpi_serve() { return 0; }
void mpi_run_everywhere(const std::string&) {}
void mpi_stop(int) {}

std::shared_ptr<DistributedRun> mpi_prepare(const Mesh&, const BoundarySet&, Method, const MethodOptions&,
                                            const std::vector<std::vector<NodeId>>&, Plan&, std::vector<double>&) {
    throw Error("mpi_prepare: dgwarp was built without MPI");
}

std::int64_t mpi_outside_hull(const DistributedRun&) { return 0; }

// One process: the collectives are the identity.
void mpi_agree(const std::exception_ptr& error) {
    if (error) std::rethrow_exception(error);
}
std::int64_t mpi_sum(std::int64_t value) { return value; }
std::vector<std::int64_t> mpi_sum(std::vector<std::int64_t> values) { return values; }
std::vector<double> mpi_sum(std::vector<double> values) { return values; }
double mpi_min(double value) { return value; }
double mpi_max(double value) { return value; }
std::int64_t mpi_min(std::int64_t value) { return value; }
std::int64_t mpi_max(std::int64_t value) { return value; }
std::vector<std::int64_t> mpi_all_gather(const std::vector<std::int64_t>& values, std::vector<std::int64_t>* counts) {
    if (counts) *counts = {static_cast<std::int64_t>(values.size())};
    return values;
}
std::vector<std::string> mpi_gather_text(const std::string& text) { return {text}; }
std::string mpi_broadcast_text(const std::string& text) { return text; }

// Each process's own part: only under mpirun with several processes.
QualitySummary case_quality(std::span<const double>, const std::vector<std::int64_t>&) {
    throw Error("case_quality: dgwarp was built without MPI");
}
RatioSummary case_ratios(std::span<const double>, const std::vector<std::int64_t>&) {
    throw Error("case_ratios: dgwarp was built without MPI");
}
std::pair<std::vector<std::int64_t>, std::int64_t> case_worst(const std::vector<std::int64_t>&, const std::vector<double>&,
                                                               const std::vector<std::int64_t>&, std::size_t) {
    throw Error("case_worst: dgwarp was built without MPI");
}
std::vector<Warning> case_warnings(const std::vector<Warning>&, std::int64_t, SharedNodeRule) {
    throw Error("case_warnings: dgwarp was built without MPI");
}

std::shared_ptr<DistributedRun> mpi_prepare_own(Method, int, const MethodOptions&, std::span<const double>,
                                                std::span<const std::int64_t>, const BoundarySet&, Plan&,
                                                std::vector<double>&, std::int64_t&) {
    throw Error("mpi_prepare_own: dgwarp was built without MPI");
}
StepReport mpi_deform_own(const DistributedRun&, std::span<const double>, const BoundaryMotion&, std::span<double>,
                          std::vector<double>&) {
    throw Error("mpi_deform_own: dgwarp was built without MPI");
}

StepReport mpi_deform(const DistributedRun&, const BoundaryMotion&, std::span<double>, std::vector<double>&) {
    throw Error("mpi_deform: dgwarp was built without MPI");
}

}  // namespace dgwarp::cli
