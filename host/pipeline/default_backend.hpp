#pragma once
// The paper method's backend when --backend is absent: the field method on
// the selected OpenCL device where that device finishes a run first, else
// its serial twin on the CPU. Measured on an H100 and on PoCL:
// docs/PERFORMANCE.md, "When the GPU pays".
#include <string>

#include "opencl/device_discovery.hpp"
#include "particles/particle_params.hpp"
#include "pipeline/distances.hpp"

namespace meshparticles {

// On the dense table a run of the paper's sizes settles in 7 to 15
// iterations; a GPU's field backend wins back its set-up (context, program,
// table upload: about 0.2 s on the H100) from about 3,000 particles.
inline constexpr std::size_t kGpuPaysFromParticlesDense = 3000;

struct DefaultBackend {
  std::string name;    // "field" or "serial-field"
  std::string reason;  // report.json's backend_from
  // On the table the same scheme on either, so the default run's particles
  // do not depend on which one the device picked (the twins make the same
  // moves).
  Scheme scheme = Scheme::monotone;
};

// `device`: what --device, $MESHPARTICLES_DEVICE or the default rule
// selects; null when no OpenCL runtime is installed.
DefaultBackend default_paper_backend(StoreKind store, std::size_t particles, const DeviceDescription* device);

}  // namespace meshparticles
