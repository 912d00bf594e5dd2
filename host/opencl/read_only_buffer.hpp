#pragma once
// A read-only device buffer holding a copy of `values`: the mesh tables the
// geodesic kernels read (rings, edge lengths, stencils).
#include <vector>

#include "opencl/opencl.hpp"

namespace meshparticles {

template <typename T>
cl::Buffer read_only_buffer(const cl::Context& context, const std::vector<T>& values) {
  // A buffer may not be empty: an empty table (a mesh without virtual
  // updates, say) gets one entry the kernel never reads.
  if (values.empty()) return cl::Buffer(context, CL_MEM_READ_ONLY, sizeof(T));
  return cl::Buffer(context, CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR, values.size() * sizeof(T),
                    const_cast<T*>(values.data()));
}

}  // namespace meshparticles
