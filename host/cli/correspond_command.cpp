// `meshparticles correspond INPUTS... --out DIR -n N`: particles that
// correspond across a population (correspondence/population_correspondence),
// each shape's evenness, and the shape model of the result
// (docs/CORRESPONDENCE.md).
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <memory>
#include <optional>
#include <string>

#include "cli/commands.hpp"
#include "cli/number_options.hpp"
#include "common/directory_lock.hpp"
#include "common/user_error.hpp"
#include "common/version.hpp"
#include "correspondence/correspondence_checkpoint.hpp"
#include "correspondence/correspondence_outputs.hpp"
#include "correspondence/shape_records.hpp"
#include "launch/batch_inputs.hpp"
#include "launch/failure.hpp"
#include "launch/launch_environment.hpp"
#include "reports/quality_report.hpp"

namespace meshparticles {

namespace {

struct CorrespondOptions {
  std::vector<std::string> inputs;
  std::string out;
  std::size_t particles = 256;
  std::uint64_t seed = 1;
  bool no_scale = false;
  std::size_t samples = 1000;
  std::size_t refine_iterations = JointRefinementOptions{}.iterations;
  double correspondence_weight = JointRefinementOptions{}.correspondence_weight;
  bool no_packing = false;
  double packing_hold = JointRefinementOptions{}.packing_hold;
  unsigned threads = 0;
  bool quiet = false;
};

std::string method_name(const JointRefinementOptions& refinement) {
  if (refinement.iterations == 0) return "template transfer";
  if (!refinement.pack) return "template transfer, then joint refinement";
  return "template transfer, then joint refinement and packing";
}

// What the result depends on, for the checkpoint: a run of other inputs
// (their paths, sizes, times) or parameters does not resume this one's.
nlohmann::json fingerprint(const CorrespondOptions& options, const std::vector<std::string>& names) {
  nlohmann::json inputs = nlohmann::json::array();
  for (const std::string& name : names) {
    std::error_code error;
    const auto size = std::filesystem::file_size(name, error);
    const auto time = std::filesystem::last_write_time(name, error).time_since_epoch().count();
    inputs.push_back({name, error ? 0 : size, error ? 0 : time});
  }
  return {{"version", program_version()},
          {"inputs", inputs},
          {"particles", options.particles},
          {"seed", options.seed},
          {"refine_iterations", options.refine_iterations},
          {"correspondence_weight", options.correspondence_weight},
          {"packing", !options.no_packing},
          {"packing_hold", options.packing_hold}};
}

void write_results(const CorrespondOptions& options, const std::vector<std::string>& names,
                   const CorrespondRequest& request, const PopulationCorrespondence& population);

// The population's particles, on every process of `share`; the leader writes the outputs.
void correspond_shared(const CorrespondOptions& options, const std::vector<std::string>& names,
                       CorrespondRequest request, ShapeShare& share) {
  // One run at a time in --out; then, before the work, the checks that it can take the outputs.
  std::optional<DirectoryLock> lock;
  if (share.leads()) {
    lock.emplace(options.out, "correspond");
    prepare_correspondence_directory(options.out, names);
  }
  request.run.particles = options.particles;
  request.run.seed = options.seed;
  request.quiet = options.quiet || !share.leads();
  request.refinement.iterations = options.refine_iterations;
  request.refinement.correspondence_weight = options.correspondence_weight;
  request.refinement.pack = !options.no_packing;
  request.refinement.packing_hold = options.packing_hold;
  const CorrespondCheckpoint checkpoint(options.out, fingerprint(options, names), share.leads(), request.quiet);
  const PopulationCorrespondence population = correspond_population(request, share, &checkpoint);
  if (!share.leads()) return;
  write_results(options, names, request, population);
  checkpoint.remove();
}

void run_correspond(const CorrespondOptions& options) {
  std::vector<std::string> notes;
  const std::vector<MeshInput> inputs = expand_batch_inputs(options.inputs, notes);
  if (inputs.size() < 2) {
    // A file given twice counts once: say so, or "got 1" for two names reads as wrong.
    std::string why;
    for (const std::string& note : notes) why += "; " + note;
    throw UserError("correspond needs at least 2 meshes, got " + std::to_string(inputs.size()) + why);
  }
  const MpiLaunch launch = mpi_launch_from_environment();
  if (!options.quiet && launch.world_rank == 0) {
    for (const std::string& note : notes) std::cerr << "meshparticles: " << note << "\n";
  }
  std::vector<std::string> names;
  CorrespondRequest request;
  for (const MeshInput& input : inputs) {
    names.push_back(input.path.string());
    request.meshes.push_back(input.path);
  }
  if (!launch.launched) {
    ShapeShare share(inputs.size(), options.threads);
    correspond_shared(options, names, request, share);
    return;
  }
#ifdef MESHPARTICLES_WITH_MPI
  const std::unique_ptr<ShapeShare> share = share_shapes_across_ranks(inputs.size(), options.threads);
  try {
    correspond_shared(options, names, request, *share);
  } catch (...) {
    // Another rank may be waiting for this one in a gather: all of them end.
    const Failure failure = describe_failure(std::current_exception());
    std::cerr << "meshparticles: " << (failure.internal ? "internal error: " : "error: ") << failure.message << "\n";
    share->abort(failure.exit_code);
  }
#else
  // Every rank would do the whole population: rank 0 does it alone, the others leave.
  if (launch.world_rank != 0) return;
  if (!options.quiet) {
    std::cerr << "meshparticles: warning: this meshparticles is built without MPI: rank 0 runs the whole population "
                 "alone and the other ranks exit (rebuild with OpenMPI installed to share the shapes out)\n";
  }
  ShapeShare share(inputs.size(), options.threads);
  correspond_shared(options, names, request, share);
#endif
}

void write_results(const CorrespondOptions& options, const std::vector<std::string>& names,
                   const CorrespondRequest& request, const PopulationCorrespondence& population) {
  const JointRefinementRecord& refinement = population.refinement;

  std::vector<PointSet> shapes;
  for (const ShapeCorrespondence& shape : population.shapes) shapes.push_back(shape.particles);
  const ShapeModel model = build_shape_model(shapes, !options.no_scale, options.samples, options.seed, options.quiet);
  const nlohmann::json params = {{"particles", options.particles}, {"seed", options.seed},
                                 {"scale", !options.no_scale}, {"samples", options.samples},
                                 {"refine_iterations", options.refine_iterations},
                                 {"correspondence_weight", options.correspondence_weight},
                                 {"packing", !options.no_packing}, {"packing_hold", options.packing_hold}};
  const ShapeModelOutputs outputs{names, &model, params};

  nlohmann::json shape_rows = nlohmann::json::array();
  for (const ShapeCorrespondence& shape : population.shapes) {
    shape_rows.push_back({{"mesh", shape.mesh.string()},
                          {"vertices", shape.vertices},
                          {"fit_rms", shape.alignment.rms},
                          {"fit_iterations", shape.alignment.iterations},
                          {"fit_from", shape.alignment.from_principal_axes ? "principal axes" : "pose as given"},
                          {"fit_runner_up", runner_up_json(shape.alignment.runner_up)},
                          {"topology", topology_json(shape.topology)},
                          {"quality", quality_json(shape.quality)}});
  }
  const nlohmann::json summary = {{"version", program_version()},
                                  {"method", method_name(request.refinement)},
                                  {"refinement", {{"overlap", refinement.overlap},
                                                  {"correspondence_step", refinement.correspondence_step},
                                                  {"packing", {{"rounds", refinement.packing_rounds},
                                                               {"released", refinement.packing_released},
                                                               {"smallest_spacing", refinement.packing_spacing},
                                                               {"correspondence_step", refinement.packing_correspondence_step}}}}},
                                  {"params", params},
                                  {"template", {{"mesh", names.front()},
                                                {"topology", topology_json(population.shapes.front().topology)},
                                                {"quality", quality_json(population.template_quality)}}},
                                  {"warnings", population.warnings},
                                  {"shapes", shape_rows},
                                  {"model", shape_model_summary(outputs)}};
  write_correspondence(options.out, population, outputs, summary);

  std::printf("shapes      %zu, %zu particles each, template %s\n", names.size(), options.particles,
              names.front().c_str());
  double worst_fit = 0;
  for (const ShapeCorrespondence& shape : population.shapes) worst_fit = std::max(worst_fit, shape.alignment.rms);
  std::printf("alignment   worst fit %.4f (rms distance at unit area)\n", worst_fit);
  std::printf("model       %lld modes; variance held by 1, 3, 5 modes:",
              static_cast<long long>(model.modes.variances.size()));
  for (const std::size_t m : {1, 3, 5}) {
    if (m <= model.quality.compactness.size()) std::printf(" %.1f%%", 100 * model.quality.compactness[m - 1]);
  }
  std::printf("\noutput      %s/{shapes/, model/, summary.json}\n", options.out.c_str());
}

}  // namespace

void add_correspond_command(CLI::App& app) {
  auto options = std::make_shared<CorrespondOptions>();
  CLI::App* command = app.add_subcommand(
      "correspond", "Particles at the same places on every shape of a population, and their shape model");
  command->add_option("inputs", options->inputs, "Mesh files, folders of meshes, .txt files listing meshes; the first is the template")
      ->required();
  command
      ->add_option("--out", options->out,
                   "Output directory: shapes/, model/, summary.json (and checkpoint/ while it runs: the same "
                   "command run again after a kill goes on from there)")
      ->required();
  add_whole_number_option(*command, "-n,--particles", options->particles, kParticleRange,
                          "Particles on every shape");
  add_whole_number_option(*command, "--seed", options->seed, kSeedRange, "Seed of the template's start and the model's draws");
  command->add_flag("--no-scale", options->no_scale, "Model: align by rotation and translation only");
  add_whole_number_option(*command, "--samples", options->samples, WholeRange{1, 1000000},
                          "Model: shapes drawn per number of modes, for specificity");
  add_whole_number_option(*command, "--refine-iterations", options->refine_iterations, WholeRange{0, 100000},
                          "Iterations of the joint refinement after the transfer (0: the transfer alone)");
  command->add_option("--correspondence-weight", options->correspondence_weight,
                      "Refinement: the correspondence step's weight against the sampling step's (0: each shape "
                      "evened out on its own)")
      ->check(CLI::Range(0.0, 100.0))
      ->capture_default_str();
  command->add_flag("--no-packing", options->no_packing,
                    "Refinement: end after the iterations, without the packing (each shape's particles pushed apart "
                    "for a growing radius, as `run` spreads them)");
  command->add_option("--packing-hold", options->packing_hold,
                      "Packing: the share of the correspondence weight it keeps (0: the evenest shapes, a looser "
                      "correspondence)")
      ->check(CLI::Range(0.0, 1.0))
      ->capture_default_str();
  add_whole_number_option(*command, "--threads", options->threads, kThreadRange,
                          "Threads per process for its shapes (0: the cores, shared among the ranks of a node); the "
                          "result is the same for any number");
  command->add_flag("-q,--quiet", options->quiet, "No progress lines");
  command->callback([options] { run_correspond(*options); });
}

}  // namespace meshparticles
