// `meshparticles batch`: the run of `run` on many meshes (batch/), one
// output folder per mesh and a summary; shared out among MPI ranks when
// started by mpirun or srun.
#include <memory>

#include "batch/batch_runner.hpp"
#include "cli/commands.hpp"
#include "cli/run_options.hpp"
#include "common/user_error.hpp"
#include "options/number_options.hpp"

namespace meshparticles {

namespace {

struct BatchOptions {
  std::vector<std::string> inputs;
  std::string out;
  RunOptionValues run;
  std::optional<double> spacing, per_area;
  std::optional<double> rank_timeout;
  bool force = false;
};

void run_batch_command(const BatchOptions& options) {
  BatchRequest request;
  request.inputs = options.inputs;
  request.out = options.out;
  request.run = run_request(options.run);
  request.read = mesh_read_options(options.run);
  request.force = options.force;
  if (options.rank_timeout) request.rank_timeout_seconds = *options.rank_timeout;
  request.quiet = options.run.quiet;
  request.count.value = double(request.run.particles);
  if (options.spacing) request.count = {ParticleCount::Rule::spacing, *options.spacing};
  if (options.per_area) request.count = {ParticleCount::Rule::per_area, *options.per_area};
  const int status = run_batch(request);
  const std::string summary = (request.out / "summary.csv").string();
  if (status == 2) throw UserError("some meshes were refused: the status and reason columns of " + summary + " say which and why", 2);
  if (status != 0) throw UserError("some meshes failed: the status and reason columns of " + summary + " say which and why", status);
}

}  // namespace

void add_batch_command(CLI::App& app) {
  auto options = std::make_shared<BatchOptions>();
  CLI::App* batch = app.add_subcommand(
      "batch", "The run of `run` on many meshes: one output folder each, summary.csv and summary.json; shared out "
               "among the ranks under mpirun or srun");
  batch->add_option("inputs", options->inputs, "Mesh files, folders of meshes, .txt files listing meshes")
      ->required();
  batch->add_option("--out", options->out, "Output directory: a folder per mesh and the summary")->required();
  add_run_options(*batch, options->run);
  CLI::Option* count = batch->get_option("-n");
  add_positive_number_option(*batch, "--spacing", options->spacing,
                             "n per mesh from the hexagonal spacing d_hex in mesh units: n = round(2A / (sqrt(3) "
                             "d_hex^2)), within 1..V")
      ->excludes(count);
  add_positive_number_option(*batch, "--per-area", options->per_area,
                             "n per mesh from particles per unit of area D: n = round(D A), within 1..V")
      ->excludes(count)
      ->excludes("--spacing");
  add_positive_number_option(*batch, "--rank-timeout", options->rank_timeout,
                             "MPI only: seconds without a word from a rank before it is taken for dead and its mesh "
                             "marked failed, the others going on (default 60; needs mpirun --enable-recovery)");
  batch->add_flag("--force", options->force,
                  "Recompute every mesh (default: keep each complete, valid output of the same mesh and options)");
  batch->callback([options] { run_batch_command(*options); });
}

}  // namespace meshparticles
