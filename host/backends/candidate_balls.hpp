#pragma once
// The candidates of the field method on local balls, kept as the particles
// move: each particle's vertex and its one-ring, counted per vertex (a
// vertex stays a candidate while any particle has it), and the balls of the
// candidates held from the store, so that the hot loops need neither the
// store's lock nor its cache. Shared by the serial twin (LocalFieldBackend)
// and the device's (LocalDeviceFieldBackend).
#include <cstdint>
#include <memory>
#include <vector>

#include "geodesics/local_distances.hpp"

namespace meshparticles {

class CandidateBalls {
 public:
  CandidateBalls(const SurfaceMesh& mesh, const LocalDistances& store);

  // A particle arrives at `vertex`: it and its one-ring count once more;
  // those that become candidates are appended to `arrivals`.
  void arrive(VertexId vertex, std::vector<VertexId>& arrivals);
  // A particle leaves `vertex`: it and its one-ring count once less; those
  // that stop being candidates are appended to `departures` (their balls
  // stay held until released).
  void depart(VertexId vertex, std::vector<VertexId>& departures);
  // No candidates (the balls stay held until released).
  void clear_counts();

  bool is_candidate(VertexId v) const { return count_[v] > 0; }
  // The candidates, in increasing id.
  std::vector<VertexId> list() const;

  // v's ball if held, else null.
  const Ball* ball(VertexId v) const { return held_[v].get(); }
  // Holds v's ball from the store (computed now if the store lacks it), unless held.
  void hold(VertexId v);
  void release(VertexId v) { held_[v].reset(); }
  void release_all();

 private:
  const SurfaceMesh& mesh_;
  const LocalDistances& store_;
  std::vector<std::uint32_t> count_;  // particles that have v among their candidates
  std::vector<std::shared_ptr<const Ball>> held_;
};

}  // namespace meshparticles
