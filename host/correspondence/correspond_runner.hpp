#pragma once
// `correspond` as one call (as batch/batch_runner is `batch`): the inputs
// expanded, the population shared among MPI ranks when started by mpirun
// or srun, the output directory held, the checkpoint kept and resumed,
// correspond_population, the shape model, and the outputs with
// summary.json (correspondence_outputs).
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "correspondence/correspond_request.hpp"

namespace meshparticles {

// What the command prints of a finished run.
struct CorrespondOutcome {
  std::vector<std::string> meshes;  // as given, the template first
  double worst_fit = 0;             // the largest rms distance of a shape's alignment, at unit area
  std::size_t modes = 0;
  std::vector<double> compactness;  // the variance held by the first m modes, for m = 1, 2, ...
};

// The outcome on the process that wrote the outputs; nothing on the others.
// Throws UserError for fewer than 2 meshes, an output directory that cannot
// take the outputs or is in use, and what correspond_population refuses;
// under MPI a failure on any rank ends every rank.
std::optional<CorrespondOutcome> run_correspond(const CorrespondRequest& request);

}  // namespace meshparticles
