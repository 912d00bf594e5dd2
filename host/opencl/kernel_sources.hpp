#pragma once
// The OpenCL C sources of kernels/, embedded in the binary at build time so
// it runs from anywhere. Setting $MESHPARTICLES_KERNEL_DIR reads them from
// that directory instead: edit a kernel and rerun, no rebuild.
#include <string>
#include <vector>

namespace meshparticles {

struct EmbeddedKernelFile {
  const char* name;  // "tiled_update.cl"
  const char* text;
};

// Generated from kernels/ by cmake/embed_kernels.cmake.
const std::vector<EmbeddedKernelFile>& embedded_kernel_files();

// The source of `file_name`, with `#include "x.h"` lines replaced by the
// text of x.h (from the same place), ready for clCreateProgramWithSource.
// #line markers keep every line's own file name and number, so a build log
// points at "field.h:3", not at a line of the pasted string.
// Throws UserError when the file does not exist.
std::string kernel_source(const std::string& file_name);

// A build log of `source` (kernel_source texts pasted together) with the
// lines a compiler counted in the whole pasted text ("<kernel>:8:1:", as
// NVIDIA's compiler writes them: it ignores #line) named by their file and
// line ("field.h:3:1:"), read back from the source's own #line markers. A
// log that already names files (PoCL's) comes back as it was.
std::string name_pasted_lines(const std::string& log, const std::string& source);

}  // namespace meshparticles
