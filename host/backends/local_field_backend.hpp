#pragma once
// The field method on local balls (`--backend serial-field` with
// `--distances local`): no V x V table anywhere. The weight between two
// vertices is w of their symmetric local distance (zero beyond the store's
// reach), exactly the dense twin's weight wherever both are within reach.
//
// F is kept only where the candidate rule reads it: at the candidates of
// the particles (each particle's vertex and one-ring), counted per vertex.
// A move from a to b subtracts a's weight from every candidate in a's ball
// and adds b's to every candidate in b's ball. A vertex that becomes a
// candidate has its ball solved by the store's helper threads while the
// other particles decide, and F summed afresh from the particles in its
// ball just before its particle reads it; until then the moves pass it by.
// All sums are in the same fixed-point units as the dense field, so they
// are exact: following the moves leaves exactly what a rebuild gives,
// whenever each sum is made.
#include "backends/candidate_balls.hpp"
#include "backends/serial_field_method.hpp"
#include "geodesics/local_distances.hpp"
#include "particles/particle_params.hpp"

namespace meshparticles {

class LocalFieldBackend final : public SerialFieldMethod {
 public:
  LocalFieldBackend(const SurfaceMesh& mesh, const LocalDistances& balls, const EnergyParams& energy,
                    WeightFormat weights, std::size_t rebuild_every);

  void rebuild_field() override;
  // For tests: F(v) in field units at a candidate v (summed now if new).
  std::int64_t field(VertexId v) {
    make_ready(v);
    return field_at(v);
  }
  // For tests: the vertices where F is kept (each particle's vertex and one-ring).
  std::vector<VertexId> candidates() const { return candidates_.list(); }

 private:
  std::int64_t field_at(VertexId v) const override { return field_[v]; }
  std::int64_t weight_units(VertexId u, VertexId v) const override;
  void field_after_move(std::size_t c, VertexId from, VertexId to) override;
  void before_moves(std::span<const VertexId> targets) override;
  void before_choice(VertexId vertex) override;

  // The weight between u and v in field units, from their balls.
  std::int64_t units_between(const Ball& from_u, VertexId u, const Ball& from_v, VertexId v) const;
  // That weight as stored (a float; field_units() of it is what F counts),
  // from the two one-sided distances d_u(v) and d_v(u).
  float weight_of_pair(float from_u_to_v, float from_v_to_u) const;
  std::int64_t units_of_distance(float d) const;
  float weight_of_distance(float d) const;  // the stored weight; 0 beyond reach
  // F(x) from the particles in x's ball.
  std::int64_t field_from_scratch(VertexId x) const;
  // Adds `delta` times `from`'s weight to F at every candidate in its ball.
  void spread_weight(VertexId from, int delta);
  // Fills spread_weights_[u] at every candidate in u's ball not known yet.
  void learn_spread_weights(VertexId u);
  // Holds candidate v's ball and sums F(v), if not done since v became one.
  void make_ready(VertexId v);

  const LocalDistances& balls_;
  Potential potential_;
  float inv_two_sigma_sq_;  // in float, as the device computes weights
  WeightFormat weights_;
  std::vector<std::int64_t> field_;  // F(v) in field units, at the candidates
  // The candidates' balls, held while they are candidates, from the time
  // they are ready (a new candidate's is null until make_ready): every ball
  // the field reads is one of these (a particle's vertex is its own first
  // candidate, ready before the particle moves there).
  CandidateBalls candidates_;
  // The weights the candidate rule reads on every decision, from a vertex
  // to each of its one-ring neighbours, in field units, parallel to
  // mesh.ring_neighbors(); each is read from the two balls the first time
  // (kNotYet before). From the balls, every decision cost two binary
  // searches per candidate, and on a big mesh each step of those missed
  // the cache.
  static constexpr std::int64_t kNotYet = -1;
  mutable std::vector<std::int64_t> ring_units_;
  // Per occupied vertex u, parallel to u's ball: the stored weight to each
  // vertex of the ball (kUnknown until read while that vertex was a held
  // candidate). A particle's arrival at u reads them and its departure
  // reads them back, so a move searches one ball per candidate, not two:
  // those searches, each a cache miss, were most of a move. Released when
  // u is left empty. (4 bytes per ball entry of the occupied vertices.)
  static constexpr float kUnknown = -1.0f;
  std::vector<std::vector<float>> spread_weights_;
  std::int64_t units_at_zero_;  // a vertex's weight with itself
};

}  // namespace meshparticles
