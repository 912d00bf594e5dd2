#pragma once
// Whether this process was started by an MPI launcher, and as which rank,
// read from the variables the launchers set (OpenMPI's mpirun, srun with
// PMIx or PMI-2) before and without MPI_Init: a batch or correspond started
// on its own never initializes MPI.
namespace meshparticles {

struct MpiLaunch {
  bool launched = false;  // under mpirun or srun
  int world_rank = 0;
  int world_size = 0;  // 0 where the launcher does not say
};

MpiLaunch mpi_launch_from_environment();

// The node's cores divided among the `node_ranks` ranks on it, at least one each.
unsigned cores_per_rank(int node_ranks);

}  // namespace meshparticles
