#include "correspondence/shape_share.hpp"

#include <algorithm>
#include <cstdlib>
#include <thread>

namespace meshparticles {

namespace {

unsigned cores_or(unsigned threads) { return threads ? threads : std::max(1u, std::thread::hardware_concurrency()); }

}  // namespace

ShapeShare::ShapeShare(std::size_t shapes, unsigned threads) : ShapeShare(shapes, 0, 1, threads) {}

ShapeShare::ShapeShare(std::size_t shapes, int rank, int processes, unsigned threads)
    : shapes_(shapes),
      // Blocks as even as they can be: the first shapes % processes ranks hold one more.
      first_(shapes * std::size_t(rank) / std::size_t(processes)),
      last_(shapes * std::size_t(rank + 1) / std::size_t(processes)),
      rank_(rank),
      processes_(processes),
      threads_(cores_or(threads)) {}

std::vector<std::size_t> ShapeShare::owned() const {
  std::vector<std::size_t> shapes;
  for (std::size_t k = first_; k < last_; ++k) shapes.push_back(k);
  return shapes;
}

void ShapeShare::abort(int exit_code) { std::exit(exit_code); }

}  // namespace meshparticles
