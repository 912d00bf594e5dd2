#pragma once
// The whole pipeline as a library call: a mesh and a request in, a result
// out - distances, start, iterations on a backend, quality. Commands (`run`,
// a batch over many meshes, a binding for another language) are thin layers
// on it; reports/run_report.hpp turns a result into report.json.
//
// Two steps, so that everything that can be refused is refused in a second,
// before the distances (minutes on a big mesh) are computed: plan_run checks
// the request against the mesh, the device and the memory; execute_run does
// the work.
#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

#include "backends/backend_factory.hpp"
#include "particles/initial_placement.hpp"
#include "particles/particle_run.hpp"
#include "particles/potentials.hpp"
#include "pipeline/distances.hpp"
#include "pipeline/paper_method.hpp"
#include "pipeline/spread_method.hpp"
#include "quality/distribution_quality.hpp"

namespace meshparticles {

struct RunRequest {
  std::string mesh_label;  // names the mesh in messages and reports: its path
  std::size_t particles = 1024;
  // Absent: spread, unless an option only the paper's method takes is given
  // (--backend, --scheme, --colors, --weights, --rebuild-every, --wg,
  // --tile, --init v0), which implies paper.
  std::optional<Method> method;
  // spread: the working mesh's vertices per particle; default kSpreadVerticesPerParticle.
  std::optional<double> vertices_per_particle;
  // spread: no edge of the working mesh longer than this many hexagonal
  // spacings; default kSpreadLongestEdge. No option sets it: correspond
  // samples its template at a resolution of its own (kTemplateLongestEdge).
  std::optional<double> longest_edge;
  // spread: rounds of relaxation; default kSpreadRelaxRounds, 0: the sweeps' vertices.
  std::optional<std::size_t> relax_rounds;
  // paper: iterations; spread: sweeps. Both stop early when nothing moves.
  std::size_t max_iterations = kDefaultMaxIterations;  // 0: the start alone, measured
  // Name empty: the default for the store (field on a table, serial-field on balls).
  BackendRequest backend = [] {
    BackendRequest unnamed;
    unnamed.name.clear();
    return unnamed;
  }();
  std::optional<Scheme> scheme;    // default: the backend's
  std::optional<unsigned> colors;  // colored only; default kDefaultColors
  Init init = Init::farthest;
  std::optional<std::size_t> start_vertex;  // an input vertex id: v0's vertex, or the first farthest sample
  std::uint64_t seed = 1;
  Potential potential = kDefaultPotential;
  std::optional<double> sigma;  // default: the rule of default_sigma
  DistancesRequest distances;   // the store (dense, local, auto), solver, cache, threads
  // --geodesic given (distances.geodesics.method): else the paper method's
  // default may choose fim, where a GPU takes the balls.
  bool geodesic_given = true;
  bool quiet = false;           // no progress lines or warnings on stderr
};

// A request checked against one mesh, with every default resolved: the
// request as asked, and what was decided in the plan's own fields.
struct RunPlan {
  RunRequest request;          // as asked, untouched
  Method method = Method::spread;
  std::string method_from;     // "--method", "default", or the option that implies paper
  // A method's own decisions: the one of its method present, the other absent.
  std::optional<SpreadPlan> spread;  // spread only
  std::optional<PaperPlan> paper;    // paper only
  EnergyParams energy;
  DistancesPlan distances;     // paper: the store decided, and its radius when local; spread: decided
                               // for the working mesh when it is built (it reads distances for quality only)
  // The solver as decided (paper's default may take fim, where a GPU takes
  // the balls), quiet as the request.
  GeodesicsRequest geodesics;
  double cutoff = kDefaultCutoff;  // local balls' in d_hex: as asked, or spread's kSpreadQualityCutoff
  PlacementRequest placement;  // start_vertex as a surface vertex
  // The host's own marches (the start, the distance to the nearest
  // particle, spread's covers): fast marching where the request's solver is
  // fim, which pays only for many balls at once (host_march_method).
  GeodesicMethod march_method = GeodesicMethod::fast_marching;
};

struct RunTimes {
  double geodesics = 0, particles = 0, quality = 0, total = 0;  // seconds
};

// What the distance step did: where the table came from, or what the local
// store computed over the run.
struct DistancesUsed {
  StoreKind kind = StoreKind::dense;
  TableSource table_source;              // dense
  LocalDistances::Statistics balls;      // local
};

struct RunResult {
  RunPlan plan;
  std::string device;      // kHostDevice or the OpenCL device's name
  DistancesUsed distances;
  // spread only: its working mesh (the mesh of start, outcome.positions
  // and distance_to_nearest where present; else the input), sweeps,
  // relaxation and evening step.
  std::optional<SpreadDetails> spread;
  std::vector<VertexId> start;
  RunOutcome outcome;      // the trace (paper) and the final positions

  // The mesh the positions are vertices of: spread's working mesh, paper's input.
  const SurfaceMesh& particle_mesh(const SurfaceMesh& input) const;
  std::vector<float> distance_to_nearest;  // per vertex, to the nearest final particle
  DistributionQuality quality;
  RunTimes seconds;
};

// Throws UserError for anything the run could not do: n out of range,
// options that do not apply, a start vertex not on the surface, sizes the
// device refuses, tables the host or the device cannot hold.
RunPlan plan_run(const SurfaceMesh& mesh, const RunRequest& request);

// Runs a plan: obtains the distances (the planned store), or uses `distances`.
RunResult execute_run(const SurfaceMesh& mesh, const RunPlan& plan);
RunResult execute_run(const SurfaceMesh& mesh, const RunPlan& plan, const DistanceStore& distances);

// plan_run, then execute_run.
RunResult run_pipeline(const SurfaceMesh& mesh, const RunRequest& request);

}  // namespace meshparticles
