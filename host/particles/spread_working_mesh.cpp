#include "particles/spread_working_mesh.hpp"

#include <algorithm>

#include "geodesics/memory_guard.hpp"
#include "particles/particle_params.hpp"

namespace meshparticles {

WorkingMeshPlan plan_working_mesh(const SurfaceMesh& input, std::size_t particles, double vertices_per_particle,
                                  double longest_edge) {
  WorkingMeshPlan plan;
  const double memory_holds = 0.5 * double(usable_host_memory_bytes()) / kSpreadBytesPerWorkingVertex;
  plan.max_vertices =
      std::max(std::size_t(std::min(double(kSpreadMaxWorkingVertices), memory_holds)), input.vertex_count());
  if (memory_holds < double(kSpreadMaxWorkingVertices) && input.vertex_count() < kSpreadMaxWorkingVertices) {
    plan.cap_set_by_memory = usable_host_memory_name();
  }
  while (double(refined_vertex_count(input, plan.levels)) < vertices_per_particle * double(particles) &&
         refined_vertex_count(input, plan.levels + 1) <= plan.max_vertices) {
    ++plan.levels;
  }
  plan.capped = double(refined_vertex_count(input, plan.levels)) < vertices_per_particle * double(particles);
  plan.longest_edge = longest_edge * hexagonal_spacing(input.area(), particles);
  return plan;
}

std::optional<WorkingMeshPlan> plan_finer_working_mesh(const SurfaceMesh& input, const WorkingMeshPlan& plan) {
  WorkingMeshPlan finer = plan;
  finer.levels += kFinerSweepsRounds;
  if (refined_vertex_count(input, finer.levels) > finer.max_vertices) return std::nullopt;
  return finer;
}

RefinedMesh build_working_mesh(const SurfaceMesh& input, const WorkingMeshPlan& plan) {
  return refine_by_midpoints_then_long_edges(input, plan.levels, plan.longest_edge, plan.max_vertices);
}

}  // namespace meshparticles
