#include "opencl/program_builder.hpp"

#include "common/user_error.hpp"
#include "opencl/kernel_sources.hpp"

namespace meshparticles {

std::string build_options(const KernelDefines& defines) {
  // Unsafe math lets the compiler reorder float sums, so the energy loops
  // vectorize (2-3x on PoCL); infinities keep their meaning (no
  // -cl-finite-math-only), which the blocked candidates and the distances
  // across components need. The order of a sum changes its last bits only;
  // the tests hold every kernel to the serial reference.
  std::string options = "-cl-std=CL1.2 -cl-unsafe-math-optimizations";
  for (const auto& [name, value] : defines) options += " -D " + name + "=" + std::to_string(value);
  return options;
}

cl::Program build_program(const cl::Context& context, const cl::Device& device,
                          const std::vector<std::string>& kernel_files, const std::string& source,
                          const std::string& options) {
  cl::Program program(context, source);
  try {
    program.build({device}, options.c_str());
  } catch (const cl::Error&) {
    std::string files;
    for (const auto& file : kernel_files) files += (files.empty() ? "" : ", ") + file;
    const std::string log = name_pasted_lines(program.getBuildInfo<CL_PROGRAM_BUILD_LOG>(device), source);
    throw UserError("OpenCL kernels failed to build (" + files + ", options '" + options + "'); build log:\n" + log);
  }
  return program;
}

}  // namespace meshparticles
