#include "pipeline/distances.hpp"

#include <chrono>
#include <cmath>
#include <iostream>
#include <numbers>

#include "common/text_format.hpp"
#include "common/user_error.hpp"
#include "geodesics/memory_guard.hpp"
#include "opencl/device_discovery.hpp"
#include "particles/particle_params.hpp"

namespace meshparticles {

// A ball of radius r holds about pi r^2 / (A / V) vertices.
double expected_ball_vertices(const SurfaceMesh& mesh, double radius) {
  return std::min(double(mesh.vertex_count()),
                  std::numbers::pi * radius * radius * double(mesh.vertex_count()) / mesh.area());
}

// A run holds the balls of the particles' vertices and one-rings (at most 7
// per particle, at most every vertex), each entry a vertex id and a float.
std::uint64_t estimated_ball_bytes(const SurfaceMesh& mesh, double radius, std::size_t particles) {
  const double per_ball = expected_ball_vertices(mesh, radius);
  const double balls = std::min(double(mesh.vertex_count()), 7.0 * double(particles));
  return std::uint64_t(balls * per_ball * double(sizeof(VertexId) + sizeof(float)));
}

StoreKind parse_store_kind(const std::string& name) {
  if (name == "dense") return StoreKind::dense;
  if (name == "local") return StoreKind::local;
  if (name == "auto") return StoreKind::automatic;
  throw UserError("unknown distance store '" + name + "' (choose dense, local or auto)");
}

std::string store_kind_name(StoreKind kind) {
  switch (kind) {
    case StoreKind::dense: return "dense";
    case StoreKind::local: return "local";
    case StoreKind::automatic: return "auto";
  }
  return "?";
}

void check_distances_request(const DistancesRequest& request) {
  if (request.cutoff && request.kind == StoreKind::dense) {
    throw UserError("--cutoff applies to --distances local and auto");
  }
}

DistancesPlan plan_distances(const SurfaceMesh& mesh, const DistancesRequest& request, std::size_t particles,
                             bool backend_needs_dense) {
  DistancesPlan plan;
  const std::uint64_t usable = usable_host_memory_bytes();
  plan.kind = request.kind;
  if (plan.kind == StoreKind::automatic) {
    // By the mesh alone, never by this machine's free memory or cache: the
    // two stores need not make the same moves, and a run's particles must
    // not depend on where it ran. A table that does not fit is refused below.
    plan.kind = backend_needs_dense || mesh.vertex_count() <= kAutoDenseVertices ? StoreKind::dense : StoreKind::local;
  }
  if (plan.kind == StoreKind::dense) {
    check_table_fits(mesh.vertex_count(), sizeof(float), usable, "distance table", usable_host_memory_name(),
                     "; --distances local holds only balls around the particles");
    return plan;
  }
  const double cutoff = request.cutoff_or_default();
  if (cutoff < 1) {
    throw UserError("--cutoff " + format_number("%g", cutoff) +
                    " is under one hexagonal spacing: particles would not see their neighbours");
  }
  plan.radius = cutoff * hexagonal_spacing(mesh.area(), particles);
  plan.ball_budget_bytes = usable / 2;
  const std::uint64_t needed = estimated_ball_bytes(mesh, plan.radius, particles);
  if (needed > plan.ball_budget_bytes) {
    throw MemoryRefusal("the local distances of " + std::to_string(particles) + " particles on " +
                        std::to_string(mesh.vertex_count()) + " vertices with --cutoff " +
                        format_number("%g", cutoff) + " need about " + gibibytes(double(needed)) +
                        " of balls at once but their budget is " + gibibytes(double(plan.ball_budget_bytes)) +
                        " (half of what may be used here, set by " + memory_room().set_by +
                        "): a smaller --cutoff or a larger -n makes the balls smaller");
  }
  return plan;
}

std::optional<DeviceDescription> fim_ball_device(const GeodesicsRequest& geodesics) {
  try {
    return select_device(geodesics.device);
  } catch (const UserError& problem) {
    if (!device_request(geodesics.device).text.empty()) throw;
    if (!geodesics.quiet) {
      std::cerr << "meshparticles: warning: " << problem.what() << "; fim solves the balls on the host\n";
    }
    return std::nullopt;
  }
}

ObtainedDistances obtain_distances(const SurfaceMesh& mesh, const GeodesicsRequest& geodesics,
                                   const DistancesPlan& plan) {
  if (plan.kind == StoreKind::dense) return obtain_distances(mesh, geodesics);
  ObtainedDistances obtained;
  obtained.kind = StoreKind::local;
  LocalDistances::Settings settings{plan.radius, geodesics.method, plan.ball_budget_bytes, geodesics.threads,
                                   geodesics.quiet, std::nullopt};
  if (geodesics.method == GeodesicMethod::fast_iterative) settings.device = fim_ball_device(geodesics);
  obtained.store = std::make_unique<LocalDistances>(mesh, settings);
  return obtained;
}

ObtainedDistances obtain_distances(const SurfaceMesh& mesh, const GeodesicsRequest& geodesics) {
  const auto started = std::chrono::steady_clock::now();
  ObtainedDistances obtained;
  obtained.store = std::make_unique<DistanceTable>(load_or_compute_distances(mesh, geodesics, obtained.source));
  obtained.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  return obtained;
}

}  // namespace meshparticles
