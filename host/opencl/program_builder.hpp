#pragma once
// Builds OpenCL programs from kernels/ at run time. Compile-time parameters
// (work-group size, tile size, ...) go in as -D options; a program that
// fails to build is a UserError whose message carries the build log.
#include <map>
#include <string>
#include <vector>

#include "opencl/opencl.hpp"

namespace meshparticles {

using KernelDefines = std::map<std::string, long long>;

// One program from several kernel files (each through kernel_source()).
cl::Program build_program(const cl::Context& context, const cl::Device& device,
                          const std::vector<std::string>& kernel_files, const KernelDefines& defines);

}  // namespace meshparticles
