#pragma once
// The field method on the device over local balls (`--backend field` with
// `--distances local`): the device twin of LocalFieldBackend, with the same
// sums bit for bit (kernels/local_field.cl).
//
// The host keeps the bookkeeping the moves need - which vertices are
// candidates (each particle's vertex and one-ring, counted), and their balls
// from the store - and the device the arithmetic: F at the candidates, the
// decisions and the scatter of each move's two rows. Balls travel as rows of
// a pool on the device (CSR), appended when a vertex becomes a candidate and
// repacked, down to the current candidates, when the pool is full. The pool
// is sized from what the candidates need, never more than the device's
// memory allows (checked before allocation, a UserError naming the bytes).
#include "backends/candidate_balls.hpp"
#include "backends/device_backend.hpp"
#include "geodesics/local_distances.hpp"
#include "opencl/growing_buffer.hpp"

namespace meshparticles {

class LocalDeviceFieldBackend final : public DeviceBackend {
 public:
  // pool_headroom: the pool holds this fraction more than the candidates
  // need when it is (re)filled (tests make it small to force repacks).
  // upload_piece: rows go to the device in pieces of about this many
  // entries (tests make it small to cut rows into many pieces).
  LocalDeviceFieldBackend(const DeviceDescription& device, const UpdateKernel& kernel, const BackendInputs& inputs,
                          const LocalDistances& balls, double pool_headroom = 1.0,
                          std::size_t upload_piece = std::size_t{1} << 22);

  // Positions that differ from the current ones in at most half the
  // particles (the monotone scheme's undo) go as moves, as a colour's
  // commit: the undo of a few moves costs what they did, not a rebuild.
  void set_positions(std::span<const VertexId> positions) override;
  double total_energy() override;

  // For tests: F at every candidate (in increasing vertex id) in field
  // units, and a rebuild of F from the current positions.
  std::vector<VertexId> candidates() const { return candidates_.list(); }
  std::vector<std::int64_t> candidate_field();
  void rebuild_field();
  // For tests: how often the pool was rewritten (the first fill included),
  // and how often F was summed from scratch at every candidate.
  std::size_t repacks() const { return repacks_; }
  std::size_t rebuilds() const { return rebuilds_; }

 private:
  cl::Event enqueue_update(cl_uint color, cl_uint colors, cl_uint particles, cl_uint rank_stacks) override;
  void positions_changed(bool resized) override;
  void after_commit(cl_uint color, cl_uint colors, std::vector<cl::Event>& events) override;
  void after_iteration(std::vector<cl::Event>& events) override;

  // The moves at `first` of the device's move list (`moves`, their copy on
  // the host): F scattered at the old candidates, rows and sums for the new.
  void apply_moves(cl_uint first, std::span<const cl_uint2> moves, std::vector<cl::Event>& events);

  // Puts the rows of `arrivals` (new candidates) into the pool, repacking it
  // when they do not fit, and tells the device which vertices are candidates.
  void place_rows(const std::vector<VertexId>& arrivals, const std::vector<VertexId>& departures);
  // Rewrites the pool with the rows of the current candidates only (their
  // balls held).
  void repack();
  // Writes the rows of `rows`, in that order, into the pool from entry
  // `at` on (row_start_host_ too); returns the entry after the last.
  std::uint64_t upload_rows(const std::vector<VertexId>& rows, std::uint64_t at);
  void upload_marks(const std::vector<cl_uint4>& changes);
  void enqueue_sums(const std::vector<VertexId>& vertices);
  // Uploads `count` items to `list` (named `what` where it cannot be
  // allocated) and launches `kernel` over them.
  void launch_over_list(cl::Kernel& kernel, GrowingBuffer& list, const char* what, const void* items,
                        std::size_t count, std::size_t item_bytes);
  void set_row_args(cl::Kernel& kernel, cl_uint first);

  const LocalDistances& balls_;
  float inv_two_sigma_sq_;
  std::size_t rebuild_every_;
  std::size_t iterations_ = 0;
  std::uint64_t pool_limit_entries_;  // what the device's memory allows

  cl::Kernel update_, scatter_, sum_, mark_, energies_kernel_;
  cl::Buffer field_, occupancy_, candidate_flags_, energies_;
  cl::Buffer row_start_, row_length_, row_vertices_, row_distances_;
  double pool_headroom_;
  std::size_t upload_piece_;  // entries
  GrowingBuffer marks_list_;  // the candidate changes of one colour
  GrowingBuffer sums_list_;   // the new candidates

  // The host's mirror of the pool: the balls whose rows are in it (those
  // of candidates and of former ones until the next repack), and where
  // each vertex's row lives, if it does.
  CandidateBalls candidates_;
  std::vector<std::uint32_t> row_start_host_;
  std::uint64_t pool_used_ = 0, pool_capacity_ = 0;
  std::size_t repacks_ = 0, rebuilds_ = 0;
};

// Throws UserError when the candidates' balls, estimated at `ball_bytes`,
// would not fit in the device's memory: checked before any ball is computed.
void check_local_field_device(const DeviceDescription& device, std::uint64_t ball_bytes);

}  // namespace meshparticles
