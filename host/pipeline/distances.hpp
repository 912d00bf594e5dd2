#pragma once
// The pipeline's distance step: the store every later step reads.
// - dense: the V x V table, from the disk cache when it holds this mesh's
//   table, else computed on all cores (and cached);
// - local: balls within a cutoff of each vertex, computed on demand
//   (geodesics/local_distances.hpp), for meshes whose table would not fit or
//   would cost more than the run.
#include <memory>
#include <optional>
#include <string>

#include "geodesics/distance_cache.hpp"
#include "geodesics/distance_store.hpp"
#include "geodesics/local_distances.hpp"

namespace meshparticles {

enum class StoreKind { dense, local, automatic };
StoreKind parse_store_kind(const std::string& name);  // "dense" | "local" | "auto"
std::string store_kind_name(StoreKind kind);

// The local store's cutoff when --cutoff is absent, in hexagonal spacings:
// the weight there is exp(-14) = 8e-7 of a neighbour's at 0, and every
// committed mesh then makes exactly the dense table's moves (at 5, 5 of the
// atrium's 1,024 particles end elsewhere; at 6, 6 of the sphere's). Measured:
// docs/PERFORMANCE.md.
inline constexpr double kDefaultCutoff = 7.0;

// `auto` takes the dense table when the backend streams its rows, or when
// it fits in a quarter of the memory and is cheap: at most this many
// vertices, or already in the cache. Else local balls. Measured:
// docs/PERFORMANCE.md.
inline constexpr std::size_t kAutoDenseVertices = 6000;

struct DistancesRequest {
  GeodesicsRequest geodesics;  // solver, table cache, threads, quiet
  StoreKind kind = StoreKind::automatic;
  std::optional<double> cutoff;  // local: in hexagonal spacings d_hex of the run's n; absent: kDefaultCutoff

  double cutoff_or_default() const { return cutoff.value_or(kDefaultCutoff); }
};

// Refuses what no store does as asked, whatever the mesh: a cutoff with the
// dense table. plan_run and measure_point_sets call it first; a batch
// before its first mesh.
void check_distances_request(const DistancesRequest& request);

// What a plan decided: the store, and for local its radius in mesh units and
// the cache budget of its balls.
struct DistancesPlan {
  StoreKind kind = StoreKind::dense;  // dense or local
  double radius = 0;
  std::uint64_t ball_budget_bytes = 0;
};

// The vertices of one ball of `radius`, estimated from the mesh's area.
double expected_ball_vertices(const SurfaceMesh& mesh, double radius);

// The bytes of the balls a run on local distances holds at once, estimated
// from the mesh's area before any is computed.
std::uint64_t estimated_ball_bytes(const SurfaceMesh& mesh, double radius, std::size_t particles);

// Decides auto and checks that the store fits before anything is computed:
// the table against host memory (dense), the balls the run will hold at once
// against their budget (local). `backend_needs_dense`: the backend streams
// whole table rows. Throws UserError.
DistancesPlan plan_distances(const SurfaceMesh& mesh, const DistancesRequest& request, std::size_t particles,
                             bool backend_needs_dense);

// Where --geodesic fim solves local balls: the device --device names (or
// $MESHPARTICLES_DEVICE, else the first GPU, else the first device), or
// none (the host's cores, by the same method, with a warning unless quiet)
// when no OpenCL runtime is usable and none was named. Throws UserError when
// the device named is not here. obtain_distances asks it; spread's plan
// asks it first, to say and check where its measurement goes.
std::optional<DeviceDescription> fim_ball_device(const GeodesicsRequest& geodesics);

struct ObtainedDistances {
  std::unique_ptr<DistanceStore> store;
  StoreKind kind = StoreKind::dense;
  TableSource source;  // dense: from the cache or computed, and the cache file
  double seconds = 0;  // wall time of this step (local: the balls come later, on demand)
};

ObtainedDistances obtain_distances(const SurfaceMesh& mesh, const GeodesicsRequest& geodesics,
                                   const DistancesPlan& plan);
// The dense table (what `geodesics`, `sweep` and `bench` measure on).
ObtainedDistances obtain_distances(const SurfaceMesh& mesh, const GeodesicsRequest& geodesics);

}  // namespace meshparticles
