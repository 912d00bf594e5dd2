#include "batch/batch_runner.hpp"

#include <iostream>

#include "batch/mesh_queue.hpp"
#include "batch/node_share.hpp"
#include "launch/launch_environment.hpp"
#include "pipeline/distances.hpp"
#ifdef MESHPARTICLES_WITH_MPI
#include "batch/mpi_work_queue.hpp"
#endif

namespace meshparticles {

namespace {

// One process, every mesh in input order.
int run_batch_alone(const BatchPlan& plan) {
  BatchLedger ledger(plan);
  LedgerQueue queue(input_order(plan), ledger);
  work_through(plan, queue);
  return ledger.finish();
}

}  // namespace

int run_batch(const BatchRequest& request) {
  check_distances_request(request.run.distances);  // refused once, not for each mesh
  const MpiLaunch launch = mpi_launch_from_environment();
#ifdef MESHPARTICLES_WITH_MPI
  if (launch.launched) return run_batch_across_ranks(request);
#else
  if (launch.launched) {
    // Every rank would run the whole batch: rank 0 does it alone, the others leave.
    if (launch.world_rank != 0) return 0;
    if (!request.quiet) {
      std::cerr << "meshparticles: warning: this meshparticles is built without MPI: rank 0 runs the whole batch "
                   "alone and the other ranks exit (rebuild with OpenMPI installed to share the meshes out)\n";
    }
  }
#endif
  BatchPlan plan = plan_batch(request, true);
  share_node(plan.request.run, 0, 1);
  return run_batch_alone(plan);
}

}  // namespace meshparticles
