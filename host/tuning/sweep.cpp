#include "tuning/sweep.hpp"

#include "backends/device_backend.hpp"
#include "backends/reference_check.hpp"
#include "backends/serial_backend.hpp"
#include "common/progress.hpp"
#include "reports/text_format.hpp"

namespace meshparticles {

namespace {

std::string first_line(const std::string& text) { return text.substr(0, text.find('\n')); }

SweepResult measure(const DeviceDescription& device, const SurfaceMesh& mesh, const DistanceTable& distances,
                    const EnergyParams& energy, const std::vector<VertexId>& positions,
                    const ReferenceChoices& reference, const UpdateKernel& kernel, const SweepSettings& settings) {
  SweepResult result{kernel, SweepStatus::ok, "", {}};
  try {
    const auto backend = make_device_backend(device, mesh, distances, energy, kernel);  // checks the limits, builds
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

std::vector<UpdateKernel> sweep_configurations(const std::vector<KernelKind>& kinds,
                                               const std::vector<std::size_t>& work_group_sizes,
                                               const std::vector<std::size_t>& tile_sizes,
                                               std::size_t candidate_slots) {
  std::vector<UpdateKernel> configurations;
  for (const KernelKind kind : kinds) {
    for (const std::size_t work_group : work_group_sizes) {
      UpdateKernel kernel;
      kernel.kind = kind;
      kernel.work_group_size = work_group;
      kernel.candidate_slots = candidate_slots;
      if (kind != KernelKind::tiled) {
        configurations.push_back(kernel);
        continue;
      }
      for (const std::size_t tile : tile_sizes) {
        kernel.tile_size = tile;
        configurations.push_back(kernel);
      }
    }
  }
  return configurations;
}

std::vector<SweepResult> run_sweep(const DeviceDescription& device, const SurfaceMesh& mesh,
                                   const DistanceTable& distances, const EnergyParams& energy,
                                   const std::vector<VertexId>& positions,
                                   const std::vector<UpdateKernel>& configurations, const SweepSettings& settings) {
  ProgressLine progress("sweep", configurations.size(), settings.quiet);
  progress.update(0, "serial reference");
  const SerialBackend serial(mesh, distances, energy);
  const ReferenceChoices reference(mesh, serial, positions);
  std::vector<SweepResult> results;
  for (const UpdateKernel& kernel : configurations) {
    progress.update(results.size(), kernel_kind_name(kernel.kind) + " " + kernel.sizes_text());
    results.push_back(measure(device, mesh, distances, energy, positions, reference, kernel, settings));
  }
  progress.update(results.size());
  progress.finish();
  return results;
}

const SweepResult* best_result(const std::vector<SweepResult>& results, KernelKind kind) {
  const SweepResult* best = nullptr;
  for (const SweepResult& result : results) {
    if (result.kernel.kind != kind || result.status != SweepStatus::ok) continue;
    if (!best || result.timing.median_ms < best->timing.median_ms) best = &result;
  }
  return best;
}

}  // namespace meshparticles
