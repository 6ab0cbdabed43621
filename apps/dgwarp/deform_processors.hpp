#pragma once
// `mpirun -np P dgwarp deform CASE -m MOTION -o OUT` where CASE is a
// decomposed OpenFOAM case of P processor folders (docs/MPI.md): every
// process runs the library's job on its own processor folder
// (dgwarp/mpi_job/processor_job.hpp); no process holds the whole mesh. The
// report (the same fields as one process's) is reduced to rank 0, which prints it.
#include <string>
#include <vector>

#include "deform_report.hpp"

namespace dgwarp::cli {

/// Rank 0: whether `a` runs this way: more than one process, one method,
/// no --plan, --untangle, --su2-config nor --rename-marker, an OpenFOAM case
/// output, and a case and motion the library's job takes
/// (processor_job_refusal). Otherwise rank 0 reads the whole case (mpi_session.hpp).
bool deforms_per_processor(const DeformArgs& a, const std::vector<Method>& methods);

/// Rank 0: every process runs the deformation on its own processor folder;
/// `given_output`: the output as given (for the report). Throws as `dgwarp
/// deform` does, on every process alike.
void run_deform_per_processor(const DeformArgs& a, const std::string& given_output);

}  // namespace dgwarp::cli
