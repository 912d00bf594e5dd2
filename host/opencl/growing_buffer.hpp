#pragma once
// A device buffer for what changes size from call to call (a colour's
// list, a set's scratch): made anew, larger, only when a call needs more
// than it holds, never smaller. What it held does not survive a regrowth.
#include <algorithm>
#include <cstddef>

#include "opencl/opencl.hpp"

namespace meshparticles {

class GrowingBuffer {
 public:
  // Room for at least `bytes`: where it holds less, a buffer a quarter
  // larger than asked (64 bytes at least) from `allocate(room)`, which
  // returns a cl::Buffer or throws. Whether it was made anew.
  template <typename Allocate>
  bool fit(std::size_t bytes, Allocate&& allocate) {
    if (bytes <= bytes_ && bytes_ > 0) return false;
    const std::size_t room = std::max<std::size_t>(bytes + bytes / 4, 64);
    buffer_ = allocate(room);
    bytes_ = room;
    return true;
  }
  const cl::Buffer& buffer() const { return buffer_; }
  std::size_t bytes() const { return bytes_; }

 private:
  cl::Buffer buffer_;
  std::size_t bytes_ = 0;
};

}  // namespace meshparticles
