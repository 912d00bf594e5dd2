#pragma once
// Builds OpenCL programs from kernels/ at run time. Compile-time parameters
// (work-group size, tile size, ...) go in as -D options; a program that
// fails to build is a UserError whose message carries the build log.
// Backends get their programs through program_cache.hpp.
#include <map>
#include <string>
#include <vector>

#include "opencl/opencl.hpp"

namespace meshparticles {

using KernelDefines = std::map<std::string, long long>;

// How a program's float arithmetic may be compiled. fast: unsafe math (sums
// reordered, products fused, approximate division where a device has it),
// what the particle kernels want. exact: each operation as written, division
// and square root correctly rounded: the same bits on every conformant
// device, for kernels whose results must not depend on the device's
// compiler (kernels/surface_voronoi.cl).
enum class FloatMath { fast, exact };

// The options every program is built with, plus `defines` as -D NAME=VALUE.
std::string build_options(const KernelDefines& defines, FloatMath math = FloatMath::fast);

// Builds `source` (the expanded text of `kernel_files`, named in errors).
cl::Program build_program(const cl::Context& context, const cl::Device& device,
                          const std::vector<std::string>& kernel_files, const std::string& source,
                          const std::string& options);

}  // namespace meshparticles
