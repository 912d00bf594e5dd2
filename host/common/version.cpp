#include "common/version.hpp"

// Set for this file alone (CMakeLists.txt), so a new version rebuilds one file.
#ifndef MESHPARTICLES_VERSION
#error "MESHPARTICLES_VERSION must come from the build (project(VERSION) in CMakeLists.txt)"
#endif

namespace meshparticles {

const std::string& program_version() {
  static const std::string version = MESHPARTICLES_VERSION;
  return version;
}

}  // namespace meshparticles
