#include "pipeline/default_backend.hpp"

#include "backends/field_backend.hpp"
#include "backends/serial_field_backend.hpp"
#include "geodesics/device_balls.hpp"

namespace meshparticles {

namespace {

// `backend`, and why: "default: NAME " + `why`.
DefaultBackend choose(const BackendDescriptor& backend, const std::string& why, Scheme scheme = Scheme::monotone,
                      std::optional<GeodesicMethod> geodesic = std::nullopt) {
  return {backend.name, "default: " + backend.name + " " + why, scheme, geodesic};
}

DefaultBackend default_on_local_balls(const DeviceDescription* device, const LocalBalls& balls) {
  // The twin's sequential loop, its balls by the request's solver (fast
  // marching unless --geodesic says otherwise) on every core.
  const auto twin = [](const std::string& why) {
    return choose(serial_field_backend(), "on local distances, " + why, Scheme::sequential);
  };
  if (!local_default_may_use_device(balls)) {
    if (balls.geodesic && *balls.geodesic != GeodesicMethod::fast_iterative) {
      return twin("--geodesic solving the balls on the host");
    }
    return twin("below the " + std::to_string(kGpuPaysFromVerticesLocal) + " vertices from which a GPU pays");
  }
  if (!device || !device->is_gpu()) return twin("no GPU selected");
  // A ball and its margin must fit a work-group's table, or the host solves
  // it by fim, 3 to 11 times slower than the twin's fast marching.
  const std::size_t slots = device_ball_slots(*device);
  if (balls.vertices_per_ball > double(slots) / 2) {
    return twin("balls of about " + std::to_string(std::size_t(balls.vertices_per_ball)) + " vertices, more than " +
                std::to_string(slots / 2) + " that the GPU " + device->name + " holds with their margin");
  }
  return choose(field_backend(),
                "on local distances, the balls by fim on the GPU " + device->name + ", which pays from " +
                    std::to_string(kGpuPaysFromVerticesLocal) + " vertices",
                Scheme::monotone, GeodesicMethod::fast_iterative);
}

}  // namespace

bool local_default_may_use_device(const LocalBalls& balls) {
  const bool fim_allowed = !balls.geodesic || *balls.geodesic == GeodesicMethod::fast_iterative;
  return fim_allowed && balls.mesh_vertices >= kGpuPaysFromVerticesLocal;
}

DefaultBackend default_paper_backend(StoreKind store, std::size_t particles, const DeviceDescription* device,
                                     const LocalBalls& balls) {
  if (store != StoreKind::dense) return default_on_local_balls(device, balls);
  if (!device) return choose(serial_field_backend(), "on the dense table, no usable OpenCL device");
  // On a CPU device the one-launch iterations beat the twin at every n
  // (PoCL, whole runs).
  if (!device->is_gpu()) return choose(field_backend(), "on the dense table, device " + device->name);
  if (particles >= kGpuPaysFromParticlesDense) {
    return choose(field_backend(), "on the dense table, the GPU " + device->name + " pays from " +
                                       std::to_string(kGpuPaysFromParticlesDense) + " particles");
  }
  return choose(serial_field_backend(), "on the dense table, below the " +
                                            std::to_string(kGpuPaysFromParticlesDense) +
                                            " particles from which the GPU " + device->name + " pays");
}

}  // namespace meshparticles
