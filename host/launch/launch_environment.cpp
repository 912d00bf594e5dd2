#include "launch/launch_environment.hpp"

#include <algorithm>
#include <cstdlib>
#include <optional>
#include <string>
#include <thread>

namespace meshparticles {

namespace {

// The first of `names` that is set to a number.
std::optional<int> first_number(std::initializer_list<const char*> names) {
  for (const char* name : names) {
    const char* value = std::getenv(name);
    if (!value || !*value) continue;
    try {
      return std::stoi(value);
    } catch (const std::exception&) {
      continue;
    }
  }
  return std::nullopt;
}

}  // namespace

MpiLaunch mpi_launch_from_environment() {
  // OpenMPI's mpirun; srun --mpi=pmix (PMIx names the rank, Slurm the size); srun --mpi=pmi2 and MPICH.
  const std::optional<int> rank = first_number({"OMPI_COMM_WORLD_RANK", "PMIX_RANK", "PMI_RANK"});
  if (!rank) return {};
  const std::optional<int> size = first_number({"OMPI_COMM_WORLD_SIZE", "PMI_SIZE", "SLURM_STEP_NUM_TASKS"});
  return {true, *rank, size.value_or(0)};
}

unsigned cores_per_rank(int node_ranks) {
  return std::max(1u, std::thread::hardware_concurrency() / unsigned(std::max(node_ranks, 1)));
}

}  // namespace meshparticles
