#include "measurement/bench_plan.hpp"

#include <algorithm>
#include <map>

#include "common/progress.hpp"
#include "common/user_error.hpp"
#include "measurement/paper_figures.hpp"
#include "fixtures/mesh_generator.hpp"
#include "pipeline/distances.hpp"
#include "pipeline/mesh_input.hpp"

namespace meshparticles {

namespace {

// The committed mesh of that name; the built-in generator's when the
// directory does not have it (outside the repository).
SurfaceMesh bench_mesh(const BenchRequest& request, const std::string& name) {
  const std::filesystem::path file = request.meshes_dir / (name + ".off");
  if (std::filesystem::exists(file)) return load_mesh(file, request.quiet);
  const auto& names = generated_mesh_names();
  if (std::find(names.begin(), names.end(), name) == names.end()) {
    throw UserError("--case: no mesh " + file.string() + " and no built-in mesh named '" + name + "'");
  }
  return generate_mesh(name);
}

}  // namespace

std::vector<CaseRequest> paper_cases() {
  std::vector<CaseRequest> cases;
  for (const auto& figures : paper_figures()) cases.push_back({figures.mesh, figures.particles});
  return cases;
}

std::vector<CaseRequest> quality_cases() { return {{"sphere", 1024}, {"torus", 512}, {"atrium", 1024}, {"patch", 100}}; }

BenchPlan plan_bench(const BenchRequest& request) {
  BenchPlan plan;
  plan.request = request;
  std::map<std::string, std::shared_ptr<const SurfaceMesh>> meshes;
  BackendRequest backend_request;
  backend_request.device = request.device;
  backend_request.tuning_file = request.tuning_file;
  for (const CaseRequest& wanted : request.cases) {
    auto& mesh = meshes[wanted.mesh];
    if (!mesh) mesh = std::make_shared<const SurfaceMesh>(bench_mesh(request, wanted.mesh));
    if (wanted.particles == 0 || wanted.particles > mesh->vertex_count()) {
      throw UserError("--case " + wanted.mesh + ":" + std::to_string(wanted.particles) +
                      " is more particles than its " + std::to_string(mesh->vertex_count()) + " vertices");
    }
    PlannedCase planned{wanted, mesh, {}};
    for (const std::string& backend : request.backends) {
      backend_request.name = backend;
      planned.backends.push_back(check_backend(backend_request, *mesh, wanted.particles));
      if (planned.backends.back().device) plan.device_name = planned.backends.back().device->name;
    }
    plan.cases.push_back(std::move(planned));
  }
  return plan;
}

void for_each_case(const BenchPlan& plan, std::size_t rows_per_case, const CaseMeasurement& measure) {
  ProgressLine progress("bench", plan.cases.size() * rows_per_case, plan.request.quiet);
  std::size_t done = 0;
  const SurfaceMesh* current_mesh = nullptr;
  ObtainedDistances distances;
  GeodesicsRequest geodesics = plan.request.geodesics;
  geodesics.quiet = true;  // the bench's own progress line is enough
  for (const PlannedCase& planned : plan.cases) {
    if (planned.mesh.get() != current_mesh) {  // one table in memory at a time
      distances = {};
      progress.update(done, planned.request.mesh + " distances");
      distances = obtain_distances(*planned.mesh, geodesics);
      current_mesh = planned.mesh.get();
    }
    measure(planned, *distances.store, [&](const std::string& what) { progress.update(done++, what); });
  }
  progress.update(done);
  progress.finish();
}

}  // namespace meshparticles
