#include "measurement/sweep.hpp"

#include <set>

#include "backends/backend_table.hpp"
#include "backends/device_backend.hpp"
#include "backends/reference_check.hpp"
#include "backends/serial_backend.hpp"
#include "common/progress.hpp"
#include "common/text_format.hpp"
#include "common/user_error.hpp"
#include "particles/initial_placement.hpp"
#include "pipeline/distances.hpp"

namespace meshparticles {

namespace {

std::string first_line(const std::string& text) { return text.substr(0, text.find('\n')); }

template <typename T>
std::vector<T> unique_in_order(const std::vector<T>& values) {
  std::vector<T> unique;
  std::set<T> seen;
  for (const T& value : values) {
    if (seen.insert(value).second) unique.push_back(value);
  }
  return unique;
}

SweepResult measure(const DeviceDescription& device, const SurfaceMesh& mesh, const DistanceStore& distances,
                    const EnergyParams& energy, const std::vector<VertexId>& positions,
                    const ReferenceChoices& reference, const UpdateKernel& kernel, const SweepSettings& settings) {
  SweepResult result{kernel, SweepStatus::ok, "", {}};
  try {
    // Checks the limits and builds the kernel.
    const auto backend = make_device_backend(device, kernel, BackendInputs{mesh, distances, energy});
    backend->set_positions(positions);
    const std::vector<VertexId> choices = backend->synchronous_choices();
    const double tolerance = choice_tolerance(kernel.weights);
    const ChoiceVerdict verdict = reference.check(choices, tolerance);
    if (verdict.wrong > 0) {
      result.status = SweepStatus::failed;
      result.reason = std::to_string(verdict.wrong) + " of " + std::to_string(positions.size()) +
                      " choices differ from the serial reference, e.g. " + verdict.first_wrong;
      return result;
    }
    if (kernel.weights == WeightFormat::half) {  // what the half table costs in choices
      const std::size_t differ = reference.check(choices).wrong;
      result.reason = std::to_string(differ) + " of " + std::to_string(positions.size()) +
                      " choices beyond 1e-5 of the reference's, all within " + format_number("%g", tolerance);
    }
    for (std::size_t w = 0; w < settings.warmups; ++w) backend->time_update_kernels(settings.scheme, settings.colors);
    std::vector<double> samples;
    for (std::size_t r = 0; r < settings.repetitions; ++r) {
      samples.push_back(backend->time_update_kernels(settings.scheme, settings.colors));
    }
    result.timing = summarize_timings(samples);
  } catch (const LimitExceeded& error) {
    result.status = SweepStatus::skipped;
    result.reason = error.what();
  } catch (const UserError& error) {  // the kernel did not build at these sizes
    result.status = SweepStatus::failed;
    result.reason = first_line(error.what());
  } catch (const cl::Error& error) {  // refused at launch (resources)
    result.status = SweepStatus::failed;
    result.reason = std::string("OpenCL call ") + error.what() + " failed: " + opencl_error_text(error.err());
  }
  return result;
}

}  // namespace

std::string sweep_status_name(SweepStatus status) {
  switch (status) {
    case SweepStatus::ok: return "ok";
    case SweepStatus::skipped: return "skipped";
    case SweepStatus::failed: return "FAILED";
  }
  return "?";
}

std::vector<UpdateKernel> sweep_configurations(const std::vector<std::string>& kernels,
                                               const std::vector<std::size_t>& work_group_sizes,
                                               const std::vector<std::size_t>& tile_sizes,
                                               std::size_t candidate_slots, WeightFormat weights) {
  std::vector<UpdateKernel> configurations;
  for (const std::string& name : unique_in_order(kernels)) {
    const BackendDescriptor& backend = find_backend(name);
    for (const std::size_t work_group : unique_in_order(work_group_sizes)) {
      UpdateKernel kernel;
      kernel.backend = &backend;
      kernel.work_group_size = work_group;
      kernel.candidate_slots = candidate_slots;
      if (backend.device->takes_weight_format) kernel.weights = weights;
      if (!backend.device->takes_tile) {
        configurations.push_back(kernel);
        continue;
      }
      for (const std::size_t tile : unique_in_order(tile_sizes)) {
        kernel.tile_size = tile;
        configurations.push_back(kernel);
      }
    }
  }
  return configurations;
}

SweepPlan plan_sweep(const SurfaceMesh& mesh, const SweepRequest& request) {
  SweepPlan plan;
  plan.request = request;
  plan.request.geodesics.quiet = request.settings.quiet;
  bool any_tile = false, any_weights = false;
  for (const std::string& name : request.kernels) {
    const BackendDescriptor& backend = find_backend(name);
    if (!backend.on_device()) {
      throw UserError("--kernel " + name + " has no update kernel to sweep (choose " +
                      choice_list(device_backend_names()) + ")");
    }
    any_tile |= backend.device->takes_tile;
    any_weights |= backend.device->takes_weight_format;
  }
  if (request.tile_sizes && !any_tile) {
    throw UserError("--tile applies to the tiled kernel, which is not swept");
  }
  if (request.weights && !any_weights) {
    throw UserError("--weights applies to the field kernel, which is not swept");
  }
  if (request.settings.repetitions == 0) {
    throw UserError("--iterations must be at least 1 (timed iterations per configuration)");
  }
  if (request.particles == 0 || request.particles > mesh.vertex_count()) {
    throw UserError("-n " + std::to_string(request.particles) + " is more particles than the " +
                    std::to_string(mesh.vertex_count()) + " vertices of " + request.mesh_label);
  }
  plan.vertices = mesh.vertex_count();
  plan.device = select_device(request.device);
  plan.energy = {request.potential, default_sigma(request.potential, mesh.area(), request.particles)};
  plan.configurations =
      sweep_configurations(request.kernels, request.work_group_sizes, request.tile_sizes.value_or(kSweepTileSizes),
                           mesh.max_valence() + 1, request.weights.value_or(WeightFormat::float32));
  return plan;
}

SweepOutcome run_sweep(const SurfaceMesh& mesh, const SweepPlan& plan) {
  const ObtainedDistances distances = obtain_distances(mesh, plan.request.geodesics);
  const std::vector<VertexId> positions = place_particles(
      mesh, {plan.request.init, plan.request.particles, plan.request.seed, std::nullopt, plan.request.geodesics.method});
  return {plan, measure_configurations(plan.device, mesh, *distances.store, plan.energy, positions,
                                       plan.configurations, plan.request.settings)};
}

std::vector<SweepResult> measure_configurations(const DeviceDescription& device, const SurfaceMesh& mesh,
                                                const DistanceStore& distances, const EnergyParams& energy,
                                                const std::vector<VertexId>& positions,
                                                const std::vector<UpdateKernel>& configurations,
                                                const SweepSettings& settings) {
  ProgressLine progress("sweep", configurations.size(), settings.quiet);
  progress.update(0, "serial reference");
  const SerialBackend serial(mesh, distances, energy);
  const ReferenceChoices reference(mesh, serial, positions);
  std::vector<SweepResult> results;
  for (const UpdateKernel& kernel : configurations) {
    progress.update(results.size(), kernel.name() + " " + kernel.sizes_text());
    results.push_back(measure(device, mesh, distances, energy, positions, reference, kernel, settings));
  }
  progress.update(results.size());
  progress.finish();
  return results;
}

const SweepResult* best_result(const std::vector<SweepResult>& results, const std::string& kernel) {
  const SweepResult* best = nullptr;
  for (const SweepResult& result : results) {
    if (result.kernel.name() != kernel || result.status != SweepStatus::ok) continue;
    if (!best || result.timing.median_ms < best->timing.median_ms) best = &result;
  }
  return best;
}

}  // namespace meshparticles
