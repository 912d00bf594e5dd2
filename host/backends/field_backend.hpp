#pragma once
// The field method on the device: with F(v) = sum_i w(d(v, p_i)) over all
// particles, a candidate's energy is E_c(v) = F(v) - w(d(v, p_c)), two reads
// instead of a sum over n. F is built by streaming n rows of the weight table
// W = w(d) and afterwards follows the moves: a particle moving from a to b
// adds row b and subtracts row a, so an iteration costs in proportion to the
// particles that moved. Contract: docs/ALGORITHM.md, "The field backend".
// On local distances the descriptor makes LocalDeviceFieldBackend instead
// (local_device_field_backend.hpp): no table, the balls as rows.
#include "backends/device_backend.hpp"

namespace meshparticles {

// field_iterations sums the particles' energies in 64 bits: below n^2 2^40,
// which fits for n < 2^12.
inline constexpr std::size_t kMaxOneLaunchParticles = 4095;

class FieldBackend : public DeviceBackend {
 public:
  // Computes W on the device from the dense distance table (float32 in the
  // distances' own buffer, or half, as kernel.weights says).
  // inputs.rebuild_every: rebuild F from scratch every that many iterations
  // (0: never; the fixed-point field does not drift).
  FieldBackend(const DeviceDescription& device, const UpdateKernel& kernel, const BackendInputs& inputs);

  double total_energy() override;

  // monotone and colored K run without the host: one launch of
  // field_iterations (one work-group, kernels/field_iterations.cl) and one
  // read for up to `count` iterations. Empty (the per-colour launches, one
  // iteration at a time) for the other schemes, for n above
  // kMaxOneLaunchParticles, with --rebuild-every, or once set_one_launch(false).
  std::vector<IterationStats> iterate_without_host(Scheme scheme, unsigned colors, std::size_t count) override;
  // For tests and measurements: the per-colour launches even where one
  // launch would serve.
  void set_one_launch(bool enabled) { one_launch_ = enabled; }

  // For tests: F(v) of every vertex in field units (2^-40), the stored
  // weights (half values widened), and a rebuild from the current positions.
  std::vector<std::int64_t> field();
  std::vector<float> weights();
  void rebuild_field();

 private:
  cl::Event enqueue_update(cl_uint color, cl_uint colors, cl_uint particles, cl_uint rank_stacks) override;
  void positions_changed(bool resized) override;
  void after_commit(cl_uint color, cl_uint colors, std::vector<cl::Event>& events) override;
  void after_iteration(std::vector<cl::Event>& events) override;
  void enqueue_measured_extras(std::vector<cl::Event>& events) override;
  cl::Event enqueue_rebuild();
  cl::NDRange vertex_range() const;
  void compute_weight_table(const cl::Program& program, const DistanceTable& distances, const EnergyParams& energy);

  std::size_t rebuild_every_;
  bool one_launch_ = true;  // false also where the device cannot run field_iterations at this work-group size
  std::size_t iterations_ = 0;
  cl::Kernel update_;
  cl::Kernel rebuild_;
  cl::Kernel apply_to_field_;
  cl::Kernel particle_energies_;
  cl::Kernel one_launch_kernel_;
  cl::Buffer weights_;
  cl::Buffer field_;      // F(v), 64-bit fixed point
  cl::Buffer occupancy_;  // particles on each vertex
  cl::Buffer energies_;   // per particle, fixed point
  cl::Buffer start_positions_;  // field_iterations: where an attempt started, for its undo
  cl::Buffer history_;          // field_iterations: what each iteration did
  std::size_t history_iterations_ = 0;
};

// The field method's descriptor (backend_table.hpp).
const BackendDescriptor& field_backend();

}  // namespace meshparticles
