#include "batch/mesh_job.hpp"

#include "batch/reusable_output.hpp"
#include "common/interruption.hpp"
#include "launch/failure.hpp"
#include "mesh/io/mesh_file.hpp"
#include "pipeline/mesh_input.hpp"
#include "reports/batch_summary.hpp"
#include "reports/file_digest.hpp"
#include "reports/run_outputs.hpp"
#include "reports/run_report.hpp"

namespace meshparticles {

MeshOutcome run_batch_mesh(const BatchPlan& plan, std::size_t index) {
  const BatchItem& item = plan.items[index];
  const std::string label = item.input.path.string();
  const std::filesystem::path directory = output_directory(plan, index);
  try {
    // One read, hashed and parsed: the digest is of the bytes the run used
    // (hashing the file after loading it gave a file replaced in between
    // the other file's digest).
    std::string sha256;
    const SurfaceMesh mesh = [&] {
      const std::vector<char> bytes = read_mesh_file(item.input.path, label);
      sha256 = bytes_sha256(bytes);
      return load_mesh(bytes, item.input.path, plan.request.quiet, plan.request.read);
    }();
    RunRequest request = plan.request.run;
    request.mesh_label = label;
    request.particles = particles_for(plan.request.count, mesh.area(), mesh.vertex_count());
    const RunPlan run_plan = plan_run(mesh, request);
    if (!plan.request.force) {
      if (const auto report = reusable_report(directory, mesh, run_plan, sha256)) {
        return {finished_row(label, item.output_name, *report), true};
      }
    }
    prepare_output_directory(directory);
    const RunResult result = execute_run(mesh, run_plan);
    const nlohmann::json report = run_report(mesh, result, directory, sha256);
    write_run_outputs(directory, mesh, result, report, request.distances.geodesics.threads);
    return {finished_row(label, item.output_name, report), false};
  } catch (const Interrupted&) {
    throw;  // stops the whole batch (Ctrl-C in Python); the summary has the meshes done
  } catch (...) {
    const Failure failure = describe_failure(std::current_exception());
    const MeshStatus status = failure.exit_code == 1 ? MeshStatus::failed : MeshStatus::refused;
    return {problem_row(label, item.output_name, status, failure.message), false};
  }
}

MeshOutcome lost_mesh_outcome(const BatchPlan& plan, std::size_t index, const std::string& reason) {
  const BatchItem& item = plan.items[index];
  return {problem_row(item.input.path.string(), item.output_name, MeshStatus::failed, reason), false};
}

}  // namespace meshparticles
