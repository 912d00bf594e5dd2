#pragma once
// The one place the Khronos C++ bindings are configured: OpenCL 1.2 (what
// PoCL 3.1 reports), exceptions on. Include this, never CL/opencl.hpp directly.
#define CL_HPP_TARGET_OPENCL_VERSION 120
#define CL_HPP_MINIMUM_OPENCL_VERSION 120
#define CL_HPP_ENABLE_EXCEPTIONS
#include <CL/opencl.hpp>

#include <string>

namespace meshparticles {

// "CL_OUT_OF_RESOURCES (-5)" for an OpenCL status code.
std::string opencl_error_text(cl_int code);

}  // namespace meshparticles
