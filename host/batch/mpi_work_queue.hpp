#pragma once
// A batch shared out among MPI ranks (built only when CMake finds MPI). Rank
// 0 hands out the meshes, biggest first, one at a time to whichever rank
// asks, and works through them itself as well: a thread of rank 0 answers
// the other ranks while its main thread runs meshes. Each rank writes its
// meshes' output folders (a file system all ranks share); rank 0 records
// every row and writes the summary. Ranks send rank 0 a heartbeat; one not
// heard from for --rank-timeout is taken for dead, its mesh recorded as
// failed, and the others go on - where the launcher lets them (OpenMPI:
// mpirun --enable-recovery; else it ends the job, and a resume finishes).
#include "batch/batch_plan.hpp"

namespace meshparticles {

// The exit status of the batch on rank 0 (batch/batch_runner.hpp); 0 on the
// other ranks. Every rank calls it with the same request.
int run_batch_across_ranks(const BatchRequest& request);

}  // namespace meshparticles
