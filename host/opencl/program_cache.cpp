#include "opencl/program_cache.hpp"

#include <map>
#include <mutex>

#include "opencl/kernel_sources.hpp"

namespace meshparticles {

namespace {

struct Cache {
  std::mutex mutex;
  std::map<cl_device_id, cl::Context> contexts;
  // Keyed by the full source text, so kernels edited under
  // $MESHPARTICLES_KERNEL_DIR are new programs.
  std::map<std::tuple<cl_device_id, std::string, std::string>, cl::Program> programs;
};

// Never destroyed: releasing OpenCL objects from static destructors can run
// after the ICD loader has gone, which crashes some runtimes at exit.
Cache& cache() {
  static Cache* const instance = new Cache;
  return *instance;
}

cl::Context context_locked(Cache& c, const cl::Device& device) {
  const auto [it, inserted] = c.contexts.try_emplace(device(), cl::Context());
  if (inserted) it->second = cl::Context(device);
  return it->second;
}

}  // namespace

cl::Context device_context(const cl::Device& device) {
  Cache& c = cache();
  const std::lock_guard lock(c.mutex);
  return context_locked(c, device);
}

cl::Program cached_program(const cl::Device& device, const std::vector<std::string>& kernel_files,
                           const KernelDefines& defines, FloatMath math) {
  std::string source;
  for (const auto& file : kernel_files) source += kernel_source(file);
  std::string options = build_options(defines, math);
  if (math == FloatMath::exact &&
      (device.getInfo<CL_DEVICE_SINGLE_FP_CONFIG>() & CL_FP_CORRECTLY_ROUNDED_DIVIDE_SQRT) != 0) {
    options += " -cl-fp32-correctly-rounded-divide-sqrt";
  }
  Cache& c = cache();
  const std::lock_guard lock(c.mutex);  // one build at a time: the compilers parallelize internally
  const auto key = std::make_tuple(device(), source, options);
  if (const auto it = c.programs.find(key); it != c.programs.end()) return it->second;
  cl::Program program = build_program(context_locked(c, device), device, kernel_files, source, options);
  c.programs.emplace(key, program);
  return program;
}

}  // namespace meshparticles
