#include "launch/failure.hpp"

#include <new>
#include <stdexcept>

#include "common/text_format.hpp"
#include "common/user_error.hpp"
#include "opencl/opencl.hpp"

namespace meshparticles {

Failure describe_failure(const std::exception_ptr& error) {
  try {
    std::rethrow_exception(error);
  } catch (const UserError& problem) {
    return {problem.exit_code(), false, one_line(problem.what())};
  } catch (const cl::Error& problem) {
    // Devices allocate lazily: a buffer they cannot hold may be refused at
    // the first launch that uses it. That is the input's size, not a bug.
    const bool out_of_memory = problem.err() == CL_MEM_OBJECT_ALLOCATION_FAILURE ||
                               problem.err() == CL_OUT_OF_RESOURCES || problem.err() == CL_OUT_OF_HOST_MEMORY;
    return {out_of_memory ? 2 : 1, false,
            std::string("OpenCL call ") + problem.what() + " failed: " + opencl_error_text(problem.err()) +
                (out_of_memory ? " (the device ran out of memory or resources: try fewer vertices or particles)" : "")};
  } catch (const std::bad_alloc&) {
    return {2, false, "out of memory"};
  } catch (const std::exception& problem) {
    return {1, true, one_line(problem.what())};
  } catch (...) {
    return {1, true, "unknown exception"};
  }
}

}  // namespace meshparticles
