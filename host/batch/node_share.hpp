#pragma once
// How the ranks on one node share it: each rank its own GPU, and the cores
// divided among them.
#include "pipeline/run_pipeline.hpp"

namespace meshparticles {

// Sets what the user left open, for rank `local_rank` of the `local_size`
// ranks on this node:
// - the device of a device backend (or of the default one, which is on a
//   device on a dense table), when neither --device nor
//   $MESHPARTICLES_DEVICE names one: the node's GPUs in turn (local rank
//   modulo their number); with no GPU (PoCL on the CPU), the default device
//   for every rank;
// - the distance solver's threads when --threads is 0: the node's cores
//   divided among its ranks (at least one each).
// Throws UserError (exit 3) when a device backend named by --backend finds
// no OpenCL runtime.
void share_node(RunRequest& run, int local_rank, int local_size);

}  // namespace meshparticles
