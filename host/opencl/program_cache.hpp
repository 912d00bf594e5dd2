#pragma once
// One OpenCL context per device, and each program built once per device,
// source text and options: backends made one after another (a sweep, a
// bench, the tests) share the context and never compile the same program
// twice. Safe to call from several threads.
#include <string>
#include <vector>

#include "opencl/program_builder.hpp"

namespace meshparticles {

// The process's context for `device`.
cl::Context device_context(const cl::Device& device);

// The program of `kernel_files` with `defines` for `device`, built in
// device_context(device) at the first request (see build_program) and
// reused after. Each caller makes its own cl::Kernel objects from it.
// FloatMath::exact adds -cl-fp32-correctly-rounded-divide-sqrt where the
// device supports it (CL_DEVICE_SINGLE_FP_CONFIG).
cl::Program cached_program(const cl::Device& device, const std::vector<std::string>& kernel_files,
                           const KernelDefines& defines, FloatMath math = FloatMath::fast);

}  // namespace meshparticles
