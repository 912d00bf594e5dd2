// meshparticles._core: the pipeline behind `meshparticles run`, `quality`,
// `devices` and `geodesics --source`, for Python. The package
// (python/meshparticles/__init__.py) adds the typed wrappers; docs/PYTHON.md.
#include "bindings.hpp"
#include "common/version.hpp"

PYBIND11_MODULE(_core, module) {
  module.doc() = "The C++ core of meshparticles (use the meshparticles package, not this module)";
  module.attr("__version__") = meshparticles::program_version();  // CMake's PROJECT_VERSION
  meshparticles::python::bind_errors(module);
  meshparticles::python::bind_mesh(module);
  meshparticles::python::bind_run(module);
  meshparticles::python::bind_quality(module);
  meshparticles::python::bind_devices(module);
  meshparticles::python::bind_geodesics(module);
  meshparticles::python::bind_batch(module);
}
