// What lets a header be compiled both as OpenCL C and as the host's C++, so
// that host and kernel share one definition (planar_source.h,
// cavity_centre.h): GLOBAL_MEMORY marks what a kernel reads from a buffer
// (nothing on the host), and the host takes sqrt, fabs, isfinite and
// INFINITY from <math.h> as OpenCL C has them built in.
#ifndef HOST_OR_DEVICE_H
#define HOST_OR_DEVICE_H

// OpenCL C 1.2 defines __OPENCL_C_VERSION__; a device's compiler also
// __OPENCL_VERSION__ (clang for NVIDIA's target offline: only the first).
#if defined(__OPENCL_C_VERSION__) || defined(__OPENCL_VERSION__)
#define GLOBAL_MEMORY __global
#else
#include <math.h>
#define GLOBAL_MEMORY
#endif

#endif
