#include "opencl/program_builder.hpp"

#include "common/user_error.hpp"
#include "opencl/kernel_sources.hpp"

namespace meshparticles {

std::string build_options(const KernelDefines& defines, FloatMath math) {
  // Unsafe math lets the compiler reorder float sums, so the energy loops
  // vectorize (2-3x on PoCL); infinities keep their meaning (no
  // -cl-finite-math-only), which the blocked candidates and the distances
  // across components need. The order of a sum changes its last bits only;
  // the tests hold every kernel to the serial reference.
  // Exact: nothing fused (FP_CONTRACT OFF in the kernel holds only without
  // unsafe math) and division and square root correctly rounded (OpenCL
  // 1.2 allows 2.5 and 3 ulp otherwise; cached_program adds the option only
  // where the device supports it).
  std::string options =
      math == FloatMath::fast ? "-cl-std=CL1.2 -cl-unsafe-math-optimizations" : "-cl-std=CL1.2";
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
