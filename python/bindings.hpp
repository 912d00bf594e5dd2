#pragma once
// The pieces of meshparticles._core, one concept per file; module.cpp
// registers them in order (errors first: the others' functions raise them).
#include <pybind11/pybind11.h>

namespace meshparticles::python {

void bind_errors(pybind11::module_& module);
void bind_mesh(pybind11::module_& module);
void bind_run(pybind11::module_& module);
void bind_quality(pybind11::module_& module);
void bind_devices(pybind11::module_& module);
void bind_geodesics(pybind11::module_& module);
void bind_batch(pybind11::module_& module);

}  // namespace meshparticles::python
