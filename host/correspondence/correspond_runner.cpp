#include "correspondence/correspond_runner.hpp"

#include <algorithm>
#include <iostream>
#include <memory>

#include "launch/batch_inputs.hpp"
#include "launch/failure.hpp"
#include "launch/launch_environment.hpp"
#include "common/atomic_directory.hpp"
#include "common/directory_lock.hpp"
#include "common/user_error.hpp"
#include "common/version.hpp"
#include "correspondence/correspondence_checkpoint.hpp"
#include "correspondence/correspondence_outputs.hpp"
#include "correspondence/shape_records.hpp"
#include "reports/quality_report.hpp"
#include "shape_model/shape_model.hpp"

namespace meshparticles {

namespace {

std::string method_name(const JointRefinementOptions& refinement) {
  if (refinement.iterations == 0) return "template transfer";
  if (!refinement.pack) return "template transfer, then joint refinement";
  return "template transfer, then joint refinement and packing";
}

PopulationRequest population_request(const CorrespondRequest& request, const std::vector<std::string>& meshes,
                                     bool leads) {
  PopulationRequest population;
  population.meshes.assign(meshes.begin(), meshes.end());
  population.run.particles = request.particles;
  population.run.seed = request.seed;
  population.quiet = request.quiet || !leads;
  population.refinement = request.refinement;
  population.deformation = request.deformation;
  return population;
}

nlohmann::json refinement_summary(const JointRefinementRecord& refinement) {
  return {{"overlap", refinement.overlap},
          {"correspondence_step", refinement.correspondence_step},
          {"packing", {{"rounds", refinement.packing_rounds},
                       {"released", refinement.packing_released},
                       {"undone", refinement.packing_undone},
                       {"smallest_spacing", refinement.packing_spacing},
                       {"correspondence_step", refinement.packing_correspondence_step}}},
          {"evening_kept", refinement.evening_kept},
          {"gap_sweeps", refinement.gap_sweeps},
          {"hole_swaps", refinement.hole_swaps}};
}

nlohmann::json shape_summary(const ShapeCorrespondence& shape) {
  return {{"mesh", shape.mesh.string()},
          {"vertices", shape.vertices},
          {"fit_rms", shape.alignment.rms},
          {"fit_iterations", shape.alignment.iterations},
          {"fit_from", shape.alignment.from_principal_axes ? "principal axes" : "pose as given"},
          {"fit_runner_up", runner_up_json(shape.alignment.runner_up)},
          {"fit_relief", relief_json(shape.alignment.relief)},
          {"topology", topology_json(shape.topology)},
          {"transfer_repaired", shape.repaired},
          {"quality", quality_json(shape.quality)}};
}

// The shape model of the result, its files and summary.json.
CorrespondOutcome write_results(const CorrespondRequest& request, const std::vector<std::string>& meshes,
                                const PopulationCorrespondence& population) {
  std::vector<PointSet> shapes;
  for (const ShapeCorrespondence& shape : population.shapes) shapes.push_back(shape.particles);
  const ShapeModel model = build_shape_model(shapes, request.scale, request.samples, request.seed, request.quiet);
  const ShapeModelOutputs outputs{meshes, &model, correspond_params(request)};

  nlohmann::json shape_rows = nlohmann::json::array();
  for (const ShapeCorrespondence& shape : population.shapes) shape_rows.push_back(shape_summary(shape));
  const nlohmann::json summary = {{"version", program_version()},
                                  {"method", method_name(request.refinement)},
                                  {"refinement", refinement_summary(population.refinement)},
                                  {"params", outputs.params},
                                  {"template", {{"mesh", meshes.front()},
                                                {"topology", topology_json(population.shapes.front().topology)},
                                                {"quality", quality_json(population.template_quality)}}},
                                  {"warnings", population.warnings},
                                  {"shapes", shape_rows},
                                  {"model", shape_model_summary(outputs)}};
  write_correspondence(request.out, population, outputs, summary);

  CorrespondOutcome outcome{meshes, 0, std::size_t(model.modes.variances.size()), model.quality.compactness};
  for (const ShapeCorrespondence& shape : population.shapes) {
    outcome.worst_fit = std::max(outcome.worst_fit, shape.alignment.rms);
  }
  return outcome;
}

// The population's particles, on every process of `share`; the leader writes the outputs.
std::optional<CorrespondOutcome> correspond_shared(const CorrespondRequest& request,
                                                   const std::vector<std::string>& meshes, ShapeShare& share) {
  // One run at a time in --out; then, before the work, the checks that it can take the outputs.
  std::optional<DirectoryLock> lock;
  if (share.leads()) {
    restore_retired_directory(request.out);  // a swap killed between its renames (no exchange) left none
    lock.emplace(request.out, "correspond");
    prepare_correspondence_directory(request.out, meshes);
  }
  const PopulationRequest population_asked = population_request(request, meshes, share.leads());
  const CorrespondCheckpoint checkpoint(request.out, checkpoint_fingerprint(request, meshes), share.leads(),
                                        population_asked.quiet);
  const PopulationCorrespondence population = correspond_population(population_asked, share, &checkpoint);
  if (!share.leads()) return std::nullopt;
  // The checkpoint goes with the folder the new set replaces; a removal
  // after it could hit the checkpoint of a run that took --out since.
  return write_results(request, meshes, population);
}

}  // namespace

std::optional<CorrespondOutcome> run_correspond(const CorrespondRequest& request) {
  std::vector<std::string> notes;
  const std::vector<MeshInput> inputs = expand_batch_inputs(request.inputs, notes);
  if (inputs.size() < 2) {
    // A file given twice counts once: say so, or "got 1" for two names reads as wrong.
    std::string why;
    for (const std::string& note : notes) why += "; " + note;
    throw UserError("correspond needs at least 2 meshes, got " + std::to_string(inputs.size()) + why);
  }
  const MpiLaunch launch = mpi_launch_from_environment();
  if (!request.quiet && launch.world_rank == 0) {
    for (const std::string& note : notes) std::cerr << "meshparticles: " << note << "\n";
  }
  std::vector<std::string> meshes;
  for (const MeshInput& input : inputs) meshes.push_back(input.path.string());
  if (!launch.launched) {
    ShapeShare share(inputs.size(), request.threads);
    return correspond_shared(request, meshes, share);
  }
#ifdef MESHPARTICLES_WITH_MPI
  const std::unique_ptr<ShapeShare> share = share_shapes_across_ranks(inputs.size(), request.threads);
  std::optional<CorrespondOutcome> outcome;
  try {
    outcome = correspond_shared(request, meshes, *share);
  } catch (...) {
    // Another rank may be waiting for this one in a gather: all of them end.
    const Failure failure = describe_failure(std::current_exception());
    std::cerr << "meshparticles: " << (failure.internal ? "internal error: " : "error: ") << failure.message << "\n";
    share->abort(failure.exit_code);
  }
  return outcome;
#else
  // Every rank would do the whole population: rank 0 does it alone, the others leave.
  if (launch.world_rank != 0) return std::nullopt;
  if (!request.quiet) {
    std::cerr << "meshparticles: warning: this meshparticles is built without MPI: rank 0 runs the whole population "
                 "alone and the other ranks exit (rebuild with OpenMPI installed to share the shapes out)\n";
  }
  ShapeShare share(inputs.size(), request.threads);
  return correspond_shared(request, meshes, share);
#endif
}

}  // namespace meshparticles
