#include "correspondence/shape_share.hpp"

#include <algorithm>
#include <cstddef>
#include <cstdlib>

#include "common/worker_threads.hpp"

namespace meshparticles {

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

void ShapeShare::gather_points(std::vector<ShapePoints>& shapes, std::size_t particles) {
  // Each shape's points row after row, then its numbers: one gather of doubles.
  std::vector<std::vector<double>> messages(shapes.size());
  for (const std::size_t k : owned()) {
    const Eigen::VectorXd flat = flattened(shapes[k].points);
    messages[k].assign(flat.begin(), flat.end());
    messages[k].insert(messages[k].end(), shapes[k].numbers.begin(), shapes[k].numbers.end());
  }
  gather(messages);
  const std::size_t coordinates = 3 * particles;
  for (std::size_t k = 0; k < shapes.size(); ++k) {
    const std::vector<double>& message = messages[k];
    shapes[k].points = unflattened(Eigen::Map<const Eigen::VectorXd>(message.data(), Eigen::Index(coordinates)));
    shapes[k].numbers.assign(message.begin() + std::ptrdiff_t(coordinates), message.end());
  }
}

void ShapeShare::abort(int exit_code) { std::exit(exit_code); }

}  // namespace meshparticles
