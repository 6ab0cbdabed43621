#pragma once
// Reductions and gathers over a communicator, for the figures a run reports
// over every process's part (part_reductions.hpp) and the text the processes
// share (names, warnings). Collective: every process of `comm` calls each
// one, in the same order. Sizes beyond MPI's int counts go in pieces
// (large_transfers.hpp).
#include <mpi.h>

#include <cstdint>
#include <string>
#include <vector>

namespace dgwarp::mpi {

/// This process's rank in `comm`, and the number of processes (not collective).
int rank_in(MPI_Comm comm);
int processes_in(MPI_Comm comm);

std::int64_t sum(MPI_Comm comm, std::int64_t value);
/// Element by element (every process gives as many).
std::vector<std::int64_t> sum(MPI_Comm comm, std::vector<std::int64_t> values);
std::vector<double> sum(MPI_Comm comm, std::vector<double> values);
double min(MPI_Comm comm, double value);
double max(MPI_Comm comm, double value);
std::int64_t min(MPI_Comm comm, std::int64_t value);
std::int64_t max(MPI_Comm comm, std::int64_t value);

/// Every process's `values`, concatenated in rank order, on every process;
/// `counts` (when given) gets each process's number of values.
std::vector<std::int64_t> all_gather(MPI_Comm comm, const std::vector<std::int64_t>& values,
                                     std::vector<std::int64_t>* counts = nullptr);

/// Every process's `text` on `root` (in rank order); empty elsewhere.
std::vector<std::string> gather_text(MPI_Comm comm, const std::string& text, int root = 0);

/// `root`'s `text` on every process (the others' `text` is not read).
std::string broadcast_text(MPI_Comm comm, const std::string& text, int root = 0);

}  // namespace dgwarp::mpi
