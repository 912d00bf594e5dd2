#include "backends/local_device_field_backend.hpp"

#include <algorithm>
#include <limits>

#include "geodesics/memory_guard.hpp"
#include "opencl/program_cache.hpp"
#include "particles/field_units.hpp"

namespace meshparticles {

namespace {

constexpr std::uint32_t kNoRow = std::numeric_limits<std::uint32_t>::max();
constexpr std::uint64_t kEntryBytes = sizeof(VertexId) + sizeof(float);  // a row entry: vertex and distance

// Arguments, in the order of kernels/local_field.cl; kRows is the first of
// the four pool arguments.
enum UpdateArg : cl_uint {
  kUpdateField, kUpdateRows, kUpdateInverse = kUpdateRows + 4, kUpdateRingOffsets, kUpdateRingNeighbors,
  kUpdateOccupancy, kUpdatePositions, kUpdateParticleCount, kUpdateColor
  // then colors, rank_stacks, chosen, claims
};
constexpr cl_uint kUpdateChosen = kUpdateColor + 3, kUpdateClaims = kUpdateColor + 4;
enum ScatterArg : cl_uint { kScatterMoves, kScatterFirst, kScatterRows, kScatterInverse = kScatterRows + 4,
                            kScatterCandidate, kScatterField, kScatterOccupancy };
// mark and sum take their list and its length first (launch_over_list).
enum SumArg : cl_uint { kSumVertices, kSumCount, kSumRows, kSumInverse = kSumRows + 4, kSumOccupancy, kSumField };
enum MarkArg : cl_uint { kMarkChanges, kMarkCount, kMarkStart, kMarkLength, kMarkCandidate };
enum EnergyArg : cl_uint { kEnergyPositions, kEnergyCount, kEnergyRows, kEnergyInverse = kEnergyRows + 4,
                           kEnergyField, kEnergies };

// Per vertex: one-rings (4 + 4 per ring entry, counted as 8 per edge),
// claims, F, occupancy, the candidate flag, row start and length; per
// particle: positions, choices, move counts and lists, energies.
std::uint64_t fixed_device_bytes(std::uint64_t vertices, std::uint64_t edges, std::uint64_t particles) {
  return 4 * (vertices + 1) + 8 * edges + (4 + 8 + 4 + 1 + 8) * vertices + 28 * particles;
}

// The row entries the device can hold: three quarters of what its memory
// leaves beside the fixed buffers (room for the scratch lists and the
// runtime), each of the two pool buffers within the largest allocation.
std::uint64_t pool_limit_entries(const DeviceDescription& device, std::uint64_t fixed_bytes) {
  const std::uint64_t global = device.global_memory_bytes;
  const std::uint64_t left = global > fixed_bytes ? (global - fixed_bytes) / 4 * 3 : 0;
  return std::min(left / kEntryBytes, std::uint64_t(device.max_allocation_bytes) / sizeof(VertexId));
}

// The refusal when the candidates' balls need more than `device` can give
// (`needed`: the bytes in words, estimated or counted).
UserError balls_beyond_device(const std::string& needed, std::uint64_t limit_bytes, const std::string& device) {
  return UserError("the field backend on local distances needs " + needed + " of distance balls on " + device +
                   ", which can give them " + gibibytes(double(limit_bytes)) +
                   ": more particles (smaller balls), a smaller --cutoff, or --backend serial-field");
}

}  // namespace

void check_local_field_device(const DeviceDescription& device, std::uint64_t ball_bytes) {
  const std::uint64_t limit = pool_limit_entries(device, 0) * kEntryBytes;
  if (ball_bytes > limit) throw balls_beyond_device("about " + gibibytes(double(ball_bytes)), limit, device.name);
}

LocalDeviceFieldBackend::LocalDeviceFieldBackend(const DeviceDescription& device, const UpdateKernel& kernel,
                                                 const BackendInputs& inputs, const LocalDistances& balls,
                                                 double pool_headroom, std::size_t upload_piece)
    : DeviceBackend(device, inputs.mesh, kernel, /*dense_table=*/false),
      balls_(balls),
      inv_two_sigma_sq_(float(inputs.energy.inv_two_sigma_sq())),
      rebuild_every_(inputs.rebuild_every),
      pool_limit_entries_(
          pool_limit_entries(device, fixed_device_bytes(vertex_count_, inputs.mesh.edge_count(), 0))),
      pool_headroom_(pool_headroom),
      upload_piece_(upload_piece),
      candidates_(inputs.mesh, balls),
      row_start_host_(inputs.mesh.vertex_count(), kNoRow) {
  if (kernel.weights != WeightFormat::float32) {
    throw UserError("--weights half applies to the field backend on the dense table; on local distances its "
                    "weights are float32");
  }
  const cl::Program built = program(device, inputs.energy.potential, {"local_field.cl", "apply_moves.cl"});
  update_ = cl::Kernel(built, "local_field_update");
  scatter_ = cl::Kernel(built, "local_field_scatter");
  sum_ = cl::Kernel(built, "local_field_sum");
  mark_ = cl::Kernel(built, "local_field_mark");
  energies_kernel_ = cl::Kernel(built, "local_field_energies");
  for (const cl::Kernel* launched : {&update_, &scatter_}) check_kernel_limits(*launched, device);

  field_ = allocate(CL_MEM_READ_WRITE, vertex_count_ * sizeof(cl_long), "the field");
  occupancy_ = allocate(CL_MEM_READ_WRITE, vertex_count_ * sizeof(cl_uint), "the occupancy");
  candidate_flags_ = allocate(CL_MEM_READ_WRITE, vertex_count_, "the candidate flags");
  row_start_ = allocate(CL_MEM_READ_WRITE, vertex_count_ * sizeof(cl_uint), "the row starts");
  row_length_ = allocate(CL_MEM_READ_WRITE, vertex_count_ * sizeof(cl_uint), "the row lengths");
  queue_.enqueueFillBuffer(row_start_, cl_uint{0}, 0, vertex_count_ * sizeof(cl_uint));
  queue_.enqueueFillBuffer(row_length_, cl_uint{0}, 0, vertex_count_ * sizeof(cl_uint));
  queue_.enqueueFillBuffer(candidate_flags_, cl_uchar{0}, 0, vertex_count_);

  update_.setArg(kUpdateField, field_);
  update_.setArg(kUpdateInverse, inv_two_sigma_sq_);
  update_.setArg(kUpdateRingOffsets, ring_offsets_);
  update_.setArg(kUpdateRingNeighbors, ring_neighbors_);
  update_.setArg(kUpdateOccupancy, occupancy_);
  update_.setArg(kUpdateClaims, claims_);
  scatter_.setArg(kScatterInverse, inv_two_sigma_sq_);
  scatter_.setArg(kScatterCandidate, candidate_flags_);
  scatter_.setArg(kScatterField, field_);
  scatter_.setArg(kScatterOccupancy, occupancy_);
  sum_.setArg(kSumInverse, inv_two_sigma_sq_);
  sum_.setArg(kSumOccupancy, occupancy_);
  sum_.setArg(kSumField, field_);
  mark_.setArg(kMarkStart, row_start_);
  mark_.setArg(kMarkLength, row_length_);
  mark_.setArg(kMarkCandidate, candidate_flags_);
  energies_kernel_.setArg(kEnergyInverse, inv_two_sigma_sq_);
  energies_kernel_.setArg(kEnergyField, field_);
}

void LocalDeviceFieldBackend::set_row_args(cl::Kernel& kernel, cl_uint first) {
  kernel.setArg(first, row_start_);
  kernel.setArg(first + 1, row_length_);
  kernel.setArg(first + 2, row_vertices_);
  kernel.setArg(first + 3, row_distances_);
}

void LocalDeviceFieldBackend::repack() {
  std::uint64_t entries_needed = 0;
  for (VertexId v = 0; v < vertex_count_; ++v) {
    if (candidates_.is_candidate(v)) entries_needed += candidates_.ball(v)->vertices.size();
  }
  if (entries_needed > pool_limit_entries_) {
    throw balls_beyond_device(gibibytes(double(entries_needed * kEntryBytes)), pool_limit_entries_ * kEntryBytes,
                              device_.name);
  }
  // Room to grow: the candidates change as the particles move.
  const auto roomy = std::uint64_t(double(entries_needed) * (1 + pool_headroom_)) + 1;
  const std::uint64_t wanted = std::min(pool_limit_entries_, roomy);
  if (wanted > pool_capacity_) {
    pool_capacity_ = wanted;
    row_vertices_ = allocate(CL_MEM_READ_ONLY, pool_capacity_ * sizeof(cl_uint), "the distance-ball rows");
    row_distances_ = allocate(CL_MEM_READ_ONLY, pool_capacity_ * sizeof(cl_float), "the distance-ball rows");
    set_row_args(update_, kUpdateRows);
    set_row_args(scatter_, kScatterRows);
    set_row_args(sum_, kSumRows);
    set_row_args(energies_kernel_, kEnergyRows);
  }
  std::vector<VertexId> kept;
  std::vector<cl_uint> starts(vertex_count_, 0), lengths(vertex_count_, 0);
  std::vector<cl_uchar> flags(vertex_count_, 0);
  for (VertexId v = 0; v < vertex_count_; ++v) {
    if (!candidates_.is_candidate(v)) {
      candidates_.release(v);
      row_start_host_[v] = kNoRow;
      continue;
    }
    kept.push_back(v);
    lengths[v] = cl_uint(candidates_.ball(v)->vertices.size());
    flags[v] = 1;
  }
  pool_used_ = upload_rows(kept, 0);
  for (const VertexId v : kept) starts[v] = row_start_host_[v];
  ++repacks_;
  write_blocking(row_start_, 0, starts.size() * sizeof(cl_uint), starts.data());
  write_blocking(row_length_, 0, lengths.size() * sizeof(cl_uint), lengths.data());
  write_blocking(candidate_flags_, 0, flags.size(), flags.data());
}

// The rows go up in pieces (by default 4 M entries, 32 MiB): one copy of
// all of them on the host would double the balls' memory at the peak (6 GB
// more on the 1M sphere).
std::uint64_t LocalDeviceFieldBackend::upload_rows(const std::vector<VertexId>& rows, std::uint64_t at) {
  std::vector<cl_uint> vertices;
  std::vector<cl_float> distances;
  const auto send = [&] {
    if (vertices.empty()) return;
    write_blocking(row_vertices_, at * sizeof(cl_uint), vertices.size() * sizeof(cl_uint),
                              vertices.data());
    write_blocking(row_distances_, at * sizeof(cl_float), distances.size() * sizeof(cl_float),
                              distances.data());
    at += vertices.size();
    vertices.clear();
    distances.clear();
  };
  for (const VertexId v : rows) {
    const Ball& ball = *candidates_.ball(v);
    row_start_host_[v] = std::uint32_t(at + vertices.size());
    vertices.insert(vertices.end(), ball.vertices.begin(), ball.vertices.end());
    distances.insert(distances.end(), ball.distances.begin(), ball.distances.end());
    if (vertices.size() >= upload_piece_) send();
  }
  send();
  return at;
}

// Kernels over a list (mark, sum) take it and its length as their first two
// arguments. The list buffer grows, never shrinks.
void LocalDeviceFieldBackend::launch_over_list(cl::Kernel& kernel, GrowingBuffer& list, const char* what,
                                               const void* items, std::size_t count, std::size_t item_bytes) {
  if (count == 0) return;
  const std::size_t bytes = count * item_bytes;
  list.fit(bytes, [&](std::size_t room) { return allocate(CL_MEM_READ_ONLY, room, what); });
  // Blocking: the list lives on the caller's stack. In order after the
  // launches before it, so the last reader of the old contents is done.
  write_blocking(list.buffer(), 0, bytes, items);
  kernel.setArg(0, list.buffer());
  kernel.setArg(1, cl_uint(count));
  launch(kernel, cl::NDRange(count));
}

void LocalDeviceFieldBackend::upload_marks(const std::vector<cl_uint4>& changes) {
  launch_over_list(mark_, marks_list_, "the candidate changes", changes.data(), changes.size(), sizeof(cl_uint4));
}

void LocalDeviceFieldBackend::enqueue_sums(const std::vector<VertexId>& vertices) {
  launch_over_list(sum_, sums_list_, "the new candidates", vertices.data(), vertices.size(), sizeof(cl_uint));
}

void LocalDeviceFieldBackend::place_rows(const std::vector<VertexId>& arrivals,
                                         const std::vector<VertexId>& departures) {
  std::vector<VertexId> missing;
  for (const VertexId v : arrivals) {
    if (!candidates_.ball(v)) missing.push_back(v);
  }
  balls_.prefetch(missing);  // on all cores
  std::uint64_t entries = 0;
  for (const VertexId v : missing) {
    candidates_.hold(v);
    entries += candidates_.ball(v)->vertices.size();
  }
  if (pool_used_ + entries > pool_capacity_) {  // rewrite with the current candidates' rows only
    repack();
    return;
  }
  pool_used_ = upload_rows(missing, pool_used_);
  std::vector<cl_uint4> changes;
  const auto change = [&](VertexId v, cl_uint candidate) {
    changes.push_back({{v, row_start_host_[v], cl_uint(candidates_.ball(v)->vertices.size()), candidate}});
  };
  for (const VertexId v : arrivals) change(v, 1);
  for (const VertexId v : departures) change(v, 0);  // the row stays until the next repack
  upload_marks(changes);
}

void LocalDeviceFieldBackend::positions_changed(bool resized) {
  if (resized) {
    check_field_particle_count(particle_count_);
    energies_ = allocate(CL_MEM_READ_WRITE, std::max<std::size_t>(1, particle_count_) * sizeof(cl_long),
                         "the particle energies");
    update_.setArg(kUpdatePositions, positions_);
    update_.setArg(kUpdateParticleCount, particle_count_);
    update_.setArg(kUpdateChosen, chosen_);
    scatter_.setArg(kScatterMoves, moves_);
    energies_kernel_.setArg(kEnergyPositions, positions_);
    energies_kernel_.setArg(kEnergyCount, particle_count_);
    energies_kernel_.setArg(kEnergies, energies_);
  }
  iterations_ = 0;
  rebuild_field();
}

// From the positions alone: the candidates, their balls (on all cores),
// a fresh pool, the occupancy and F at every candidate.
void LocalDeviceFieldBackend::rebuild_field() {
  const std::vector<VertexId> now = positions();
  candidates_.clear_counts();
  std::vector<VertexId> ignored;
  std::vector<cl_uint> occupancy(vertex_count_, 0);
  for (const VertexId p : now) {
    candidates_.arrive(p, ignored);
    ++occupancy[p];
  }
  const std::vector<VertexId> all = candidates_.list();
  balls_.prefetch(all);
  for (const VertexId v : all) candidates_.hold(v);
  repack();
  write_blocking(occupancy_, 0, occupancy.size() * sizeof(cl_uint), occupancy.data());
  enqueue_sums(all);
  wait_for_device();
  ++rebuilds_;
}

cl::Event LocalDeviceFieldBackend::enqueue_update(cl_uint color, cl_uint colors, cl_uint particles,
                                                  cl_uint rank_stacks) {
  return launch_update(update_, kUpdateColor, color, colors, particles, rank_stacks);
}

// The moves of the colour come back to the host, which needs them for the
// candidates: the device scatters them into F at the old candidates, then
// the new candidates get their rows and F summed afresh (with the particles
// already moved), the old ones that no particle reads any more are unmarked.
void LocalDeviceFieldBackend::after_commit(cl_uint color, cl_uint colors, std::vector<cl::Event>& events) {
  cl_uint count = 0;
  read_blocking(move_counts_, color * sizeof(cl_uint), sizeof(cl_uint), &count);
  if (count == 0) return;
  const cl_uint first = color * ((particle_count_ + colors - 1) / colors);  // as apply_moves.cl
  std::vector<cl_uint2> moves(count);
  read_blocking(moves_, first * sizeof(cl_uint2), count * sizeof(cl_uint2), moves.data());
  apply_moves(first, moves, events);
}

// Exact in any grouping (F is a fixed-point sum), so the moves to an
// earlier set of positions can go as one colour's, from the front of the
// move list. Beyond half the particles a rebuild is cheaper.
void LocalDeviceFieldBackend::set_positions(std::span<const VertexId> positions) {
  if (positions.size() != particle_count_) return DeviceBackend::set_positions(positions);
  const std::vector<VertexId> before = this->positions();
  std::vector<cl_uint2> moves;
  for (std::size_t i = 0; i < positions.size(); ++i) {
    if (before[i] != positions[i]) moves.push_back({{before[i], positions[i]}});
  }
  if (2 * moves.size() > positions.size()) return DeviceBackend::set_positions(positions);
  write_blocking(positions_, 0, positions.size() * sizeof(cl_uint), positions.data());
  if (moves.empty()) return;
  write_blocking(moves_, 0, moves.size() * sizeof(cl_uint2), moves.data());
  std::vector<cl::Event> events;
  apply_moves(0, moves, events);
  wait_for_device();
}

void LocalDeviceFieldBackend::apply_moves(cl_uint first, std::span<const cl_uint2> moves,
                                          std::vector<cl::Event>& events) {
  if (moves.empty()) return;
  scatter_.setArg(kScatterFirst, first);
  const std::size_t group = kernel_.work_group_size;
  cl::Event event;
  launch(scatter_, cl::NDRange(std::size_t(2) * moves.size() * group), cl::NDRange(group), &event);
  events.push_back(event);

  // Every arrival first, then every departure: a vertex that stays a
  // candidate is never dropped and re-added, so its F stays the scattered one.
  std::vector<VertexId> arrivals, departures;
  for (const cl_uint2& move : moves) candidates_.arrive(move.s[1], arrivals);
  for (const cl_uint2& move : moves) candidates_.depart(move.s[0], departures);
  place_rows(arrivals, departures);
  enqueue_sums(arrivals);
}

void LocalDeviceFieldBackend::after_iteration(std::vector<cl::Event>& /*events*/) {
  ++iterations_;
  if (rebuild_every_ > 0 && iterations_ % rebuild_every_ == 0) rebuild_field();
}

std::vector<std::int64_t> LocalDeviceFieldBackend::candidate_field() {
  std::vector<std::int64_t> field(vertex_count_);
  read_blocking(field_, 0, field.size() * sizeof(cl_long), field.data());
  std::vector<std::int64_t> at_candidates;
  for (const VertexId v : candidates()) at_candidates.push_back(field[v]);
  return at_candidates;
}

double LocalDeviceFieldBackend::total_energy() {
  std::vector<std::int64_t> energies(particle_count_);
  if (particle_count_ == 0) return 0;
  launch(energies_kernel_, cl::NDRange(particle_count_));
  read_blocking(energies_, 0, energies.size() * sizeof(cl_long), energies.data());
  return pair_energy(energies);
}

}  // namespace meshparticles
