#pragma once
// The paper method's backend when --backend is absent: the field method on
// the selected OpenCL device where that device finishes a run first, else
// its serial twin on the CPU. Measured on an H100 and on PoCL:
// docs/PERFORMANCE.md, "When the GPU pays".
#include <optional>
#include <string>

#include "opencl/device_discovery.hpp"
#include "particles/particle_params.hpp"
#include "pipeline/distances.hpp"

namespace meshparticles {

// On the dense table a run of the paper's sizes settles in 7 to 15
// iterations; a GPU's field backend wins back its set-up (context, program,
// table upload: about 0.2 s on the H100) from about 3,000 particles.
inline constexpr std::size_t kGpuPaysFromParticlesDense = 3000;

// On local balls a GPU pays from this many vertices: its field backend,
// the balls solved on it by the fast iterative method (--geodesic fim),
// where a ball fits a work-group's table. Measured on an H200 against its
// 16 cores' serial-field with fast marching (whole runs, n = V/10, the
// default cutoff): at par at 100,000 vertices (0.87 - 1.05x, the atrium),
// 1.13 - 1.39x at 149,000, 1.52 - 1.68x at 199,000, 1.84x at 1,000,000
// (docs/PERFORMANCE.md).
inline constexpr std::size_t kGpuPaysFromVerticesLocal = 125000;

// What the default on local balls looks at besides the device.
struct LocalBalls {
  std::size_t mesh_vertices = 0;
  double vertices_per_ball = 0;  // expected, from the radius and the mesh's area
  // --geodesic as given: the GPU takes the balls only by fim; absent, the
  // default may choose fim.
  std::optional<GeodesicMethod> geodesic;
};

struct DefaultBackend {
  std::string name;    // field_backend()'s or serial_field_backend()'s
  std::string reason;  // report.json's backend_from
  // On the table the same scheme on either, so the default run's particles
  // do not depend on which one the device picked (the twins make the same
  // moves).
  Scheme scheme = Scheme::monotone;
  // Set where the default chose the solver too: fim for a GPU's balls.
  std::optional<GeodesicMethod> geodesic;
};

// `device`: what --device, $MESHPARTICLES_DEVICE or the default rule
// selects; null when no OpenCL runtime is installed. `balls`: local only.
DefaultBackend default_paper_backend(StoreKind store, std::size_t particles, const DeviceDescription* device,
                                     const LocalBalls& balls = {});

// Whether the default on local balls of this mesh would look for a device
// (a device is selected only then: on the table always).
bool local_default_may_use_device(const LocalBalls& balls);

}  // namespace meshparticles
