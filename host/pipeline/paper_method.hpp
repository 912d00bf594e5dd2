#pragma once
// paper, the paper's method: its energy, sigma rule and one-ring moves on
// the input's vertices, iterated on a backend (serial, naive, tiled, field,
// ...) over a distance store of the input. plan_run and execute_run
// (pipeline/run_pipeline.hpp) call it for Method::paper.
#include <optional>
#include <string>

#include "backends/backend_factory.hpp"
#include "geodesics/distance_store.hpp"
#include "mesh/surface_mesh.hpp"
#include "particles/particle_params.hpp"

namespace meshparticles {

// What plan_run decides for paper alone (RunPlan::paper): the backend and
// how it updates.
struct PaperPlan {
  CheckedBackend backend;
  std::string backend_from;  // "--backend", or why the default is what it is
  Scheme scheme = Scheme::colored;
  unsigned colors = kDefaultColors;
};

struct RunRequest;
struct RunPlan;
struct RunResult;

// The first option given that only the paper's method takes; none if none.
// Such an option implies paper where --method is absent.
std::optional<std::string> paper_only_option(const RunRequest& request);

// paper's part of plan_run, after the checks common to every method:
// refuses spread's options, plans the store, chooses the backend (and the
// device, and the solver where a GPU takes the balls) and checks it.
void plan_paper(const SurfaceMesh& mesh, const RunRequest& request, RunPlan& plan);

// paper's execute_run on a store of the input: the start, the iterations on
// the planned backend, the quality.
RunResult execute_paper(const SurfaceMesh& mesh, const RunPlan& plan, const DistanceStore& distances);

}  // namespace meshparticles
