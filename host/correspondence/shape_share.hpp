#pragma once
// Which shapes of a population this process works on, and how what their
// owners found reaches every process. One process owns every shape. Under
// mpirun each rank owns a block of consecutive shapes (mpi_shape_share):
// it loads, fits and moves only those, and what an iteration needs of every
// shape (the particles' places, for the population's alignment and model)
// is gathered from the owners. Every process then computes the population's
// step from the same numbers in the same order, so the result is the same,
// to the bit, for any number of processes.
#include <cstddef>
#include <memory>
#include <string>
#include <vector>

#include "shape_model/corresponding_points.hpp"

namespace meshparticles {

// What a process tells the others of one of its shapes: its particles'
// places, and a few numbers of the step (the same count for every shape).
struct ShapePoints {
  PointSet points;
  std::vector<double> numbers;
};

class ShapeShare {
 public:
  // One process: every one of `shapes`, on `threads` threads (0: every core).
  explicit ShapeShare(std::size_t shapes, unsigned threads = 0);
  virtual ~ShapeShare() = default;
  ShapeShare(const ShapeShare&) = delete;
  ShapeShare& operator=(const ShapeShare&) = delete;

  std::size_t shapes() const { return shapes_; }
  bool owns(std::size_t shape) const { return shape >= first_ && shape < last_; }
  std::vector<std::size_t> owned() const;
  // The process that writes the outputs and the checkpoints of the whole population.
  bool leads() const { return rank_ == 0; }
  // Threads for this process's own shapes.
  unsigned threads() const { return threads_; }
  int processes() const { return processes_; }

  // On return every process holds every shape's `values[k]`, as its owner
  // filled it (lengths may differ between shapes).
  virtual void gather(std::vector<std::vector<double>>& values) { (void)values; }
  virtual void gather(std::vector<std::string>& texts) { (void)texts; }
  // Every shape's points (`particles` rows) and numbers, as its owner filled them, on every process.
  void gather_points(std::vector<ShapePoints>& shapes, std::size_t particles);
  // The leader's `values` on every process.
  virtual void broadcast(std::vector<double>& values) { (void)values; }
  virtual void broadcast(std::string& text) { (void)text; }
  // Ends every process: what stops one stops the population (a rank left
  // waiting in a gather would wait for ever).
  [[noreturn]] virtual void abort(int exit_code);

 protected:
  // Rank `rank` of `processes`: the shapes' block of its rank.
  ShapeShare(std::size_t shapes, int rank, int processes, unsigned threads);

 private:
  std::size_t shapes_ = 0, first_ = 0, last_ = 0;
  int rank_ = 0, processes_ = 1;
  unsigned threads_ = 1;
};

// The share of the rank this process is under mpirun (it initializes MPI,
// and finalizes it when destroyed), on `threads` threads (0: the node's
// cores divided among its ranks). Only in a build with MPI.
std::unique_ptr<ShapeShare> share_shapes_across_ranks(std::size_t shapes, unsigned threads);

}  // namespace meshparticles
