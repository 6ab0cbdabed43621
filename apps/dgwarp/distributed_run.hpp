#pragma once
// mpi_session.hpp's DistributedRun with MPI (its sources only): the
// library's root-driven run, or this process's plan over its own part.
#include <optional>

#include "dgwarp/mpi/root_session.hpp"
#include "mpi_session.hpp"

namespace dgwarp::cli {

struct DistributedRun {
    std::optional<mpi::RootRun> root;  // rank 0 holds the whole mesh (mpi_prepare)
    std::optional<mpi::PartPlan> own;  // each process its own part (mpi_prepare_own)
};

}  // namespace dgwarp::cli
