#pragma once
// Runs a batch: alone, or shared out among MPI ranks when the program was
// built with MPI and started by mpirun or srun (batch/mpi_work_queue.hpp).
#include "batch/batch_plan.hpp"

namespace meshparticles {

// Returns the exit status: 0 when every mesh is ok, 2 when some input was
// refused (the summary says which), 1 when one failed. Throws UserError for
// what stops the whole batch before any mesh: its inputs, --out, no OpenCL
// runtime for a device backend.
int run_batch(const BatchRequest& request);

}  // namespace meshparticles
