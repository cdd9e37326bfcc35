// ProcessGroup over MPI_COMM_WORLD (Open MPI; docs/distributed.md). Compiled only when PATHSPACE_MPI
// is on; job_group.h decides whether a run uses it.
#pragma once

#include <memory>

#include "pathspace/parallel/process_group.h"

namespace pathspace::cli {

// Initialises MPI (funnelled threads: only the render thread communicates) on the first call;
// MPI_Finalize runs at exit.
std::shared_ptr<ProcessGroup> mpi_world();
// MPI_Abort of the whole job when MPI is running; returns otherwise.
void mpi_abort(int exit_code);

}  // namespace pathspace::cli
