// `meshparticles run`: the pipeline (pipeline/run_pipeline.hpp) on one mesh,
// its files (reports/run_outputs.hpp) and a summary on stdout.
#include <cstdio>
#include <filesystem>
#include <memory>
#include <optional>

#include "cli/commands.hpp"
#include "cli/run_options.hpp"
#include "common/directory_lock.hpp"
#include "common/memory_limits.hpp"
#include "pipeline/mesh_input.hpp"
#include "pipeline/run_pipeline.hpp"
#include "reports/file_digest.hpp"
#include "reports/quality_report.hpp"
#include "reports/run_outputs.hpp"
#include "reports/run_report.hpp"

namespace meshparticles {

namespace {

struct RunCommandOptions {
  std::string mesh;
  std::string out = "out";
  RunOptionValues run;
};

void print_summary(const SurfaceMesh& mesh, const RunResult& result, const std::string& out) {
  const IterationFigures figures = iteration_figures(result);
  std::printf("mesh        %s (%zu vertices)\n", result.plan.request.mesh_label.c_str(), mesh.vertex_count());
  switch (result.plan.method) {
    case Method::spread: {
      const RefinedMesh& working = *result.spread->working;
      std::printf("particles   %zu, spread on a working mesh of %zu vertices (%u rounds of splitting edges)\n",
                  result.plan.request.particles, working.mesh.vertex_count(), working.levels);
      std::printf("sweeps      %zu (%s)\n", figures.iterations_run, figures.stopped.c_str());
      std::printf("time        %.3f ms/sweep", figures.avg_iteration_ms);
      break;
    }
    case Method::paper: {
      const PaperPlan& paper = *result.plan.paper;
      std::printf("particles   %zu, %s on %s, scheme %s\n", result.plan.request.particles,
                  paper.backend.name().c_str(), result.device.c_str(), scheme_name(paper.scheme).c_str());
      std::printf("iterations  %zu (%s)\n", figures.iterations_run, figures.stopped.c_str());
      std::printf("energy      %.6g -> %.6g\n", *figures.initial_energy, figures.final_energy);
      std::printf("time        %.3f ms/iteration", figures.avg_iteration_ms);
      if (figures.avg_kernel_ms) std::printf(" (update kernels %.3f ms)", *figures.avg_kernel_ms);
      break;
    }
  }
  std::printf("\nquality     %s", quality_line(result.quality).c_str());
  std::printf("\noutput      %s/{particles.particles, particles.csv, report.json, particles.ply, "
              "mesh_distance.vtk, mesh_distance.vtp}\n",
              out.c_str());
}

void run_run(RunCommandOptions options) {
  RunRequest request = run_request(options.run);
  const SurfaceMesh mesh = load_mesh_or_default(options.mesh, request.quiet, mesh_read_options(options.run));
  request.mesh_label = options.mesh;
  const RunPlan plan = plan_run(mesh, request);
  prepare_output_directory(options.out);  // before the long work, not after
  // Held to the last file: a second run into the same --out is refused, not
  // left to replace this one's set (both once ended with exit 0).
  const DirectoryLock lock(options.out, "run");
  const RunResult result = execute_run(mesh, plan);
  // The built-in sphere has no file to digest.
  const bool from_file = std::filesystem::is_regular_file(options.mesh);
  const nlohmann::json report =
      run_report(mesh, result, options.out, from_file ? std::optional(file_sha256(options.mesh)) : std::nullopt);
  naming_memory_failures(options.out, "writing the outputs", [&] {
    write_run_outputs(options.out, mesh, result, report, request.distances.geodesics.threads);
  });
  print_summary(mesh, result, options.out);
}

}  // namespace

void add_run_command(CLI::App& app) {
  auto options = std::make_shared<RunCommandOptions>();
  CLI::App* run = app.add_subcommand("run", "Spread particles over a mesh (default: the sphere, 1024 particles)");
  run->add_option("mesh", options->mesh, "Mesh file (default: meshes/sphere.off, else the built-in sphere)");
  add_run_options(*run, options->run);
  run->add_option("--out", options->out, "Output directory")->capture_default_str();
  run->callback([options] { run_run(*options); });
}

}  // namespace meshparticles
