#pragma once
// Geodesic balls on an OpenCL device, many at once: the fast iterative
// method (fast_iterative.hpp) run by kernels/fim_balls.cl, one work-group
// per ball with the ball in local memory. The balls are what
// FastIterativeMethod::solve_ball gives, within the method's convergence
// (the device rounds in float, the host in double; docs/GEODESICS.md says
// how close). A ball too big for a work-group's table is solved on the
// host by the same method, so every ball comes back whatever its size.
#include <functional>
#include <span>
#include <vector>

#include "geodesics/fast_iterative.hpp"
#include "opencl/device_discovery.hpp"

namespace meshparticles {

// The most vertices (a ball and its margin) one work-group of `device`
// holds: its table, as big as the device's local memory allows.
std::size_t device_ball_slots(const DeviceDescription& device);

// Throws UserError (one line, naming the device) when the buffers of the
// balls on a mesh of `vertices` would not fit `device`: a plan's check from
// the count alone, before the mesh is built. The solver checks its mesh's
// own sizes again when it is made.
void check_device_balls_fit(const DeviceDescription& device, std::uint64_t vertices);

class DeviceBallSolver {
 public:
  struct Statistics {
    std::size_t balls = 0;
    std::size_t solved_on_host = 0;  // too big for the device's table
    std::size_t launches = 0;
    double kernel_seconds = 0;  // the kernels alone (profiling events)
    double seconds = 0;         // everything: uploads, kernels, reads, the host's balls
  };

  // `host` solves the balls the device cannot hold, on `threads` threads
  // (0: every core); it is read, not kept beyond this solver's life, and
  // lends its stencils to the device. Throws UserError when the mesh's
  // buffers would not fit the device.
  DeviceBallSolver(const SurfaceMesh& mesh, const FastIterativeMethod& host, const DeviceDescription& device,
                   unsigned threads = 1);

  // The ball of radius `radius` around each of `sources`, in their order.
  // `solved`, when given, hears how many are done, after each launch and
  // every few of the host's balls (which may take a second each).
  std::vector<Ball> solve_balls(std::span<const VertexId> sources, double radius,
                                const std::function<void(std::size_t)>& solved = {});

  // The most vertices (the ball and its margin) one work-group holds.
  std::size_t slots() const { return std::size_t{1} << slot_bits_; }
  std::size_t work_group_size() const { return work_group_size_; }
  const Statistics& statistics() const { return statistics_; }

 private:
  struct Launch;
  // Queues the kernel for launch.count sources from launch.first.
  void enqueue(std::span<const VertexId> sources, Launch& launch);
  // Waits for the launch and reads its balls.
  void read_back(Launch& launch);

  const FastIterativeMethod& host_;
  std::vector<SolverScratch> host_scratch_;  // one per thread solving the host's balls
  DeviceDescription device_;
  unsigned slot_bits_;
  std::size_t work_group_size_;
  std::size_t balls_per_launch_;
  cl::Context context_;
  cl::CommandQueue queue_;
  cl::Kernel kernel_;
  cl::Buffer ring_offsets_, ring_neighbors_, edge_lengths_, triangle_offsets_, triangles_, virtual_offsets_,
      virtual_updates_;
  cl::Buffer sources_, ball_vertices_, ball_distances_, ball_sizes_, ball_starts_, entries_used_;
  Statistics statistics_;
};

}  // namespace meshparticles
