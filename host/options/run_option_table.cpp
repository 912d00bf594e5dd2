#include "options/run_option_table.hpp"

#include <stdexcept>

#include "backends/backend_table.hpp"
#include "common/text_format.hpp"
#include "particles/particle_params.hpp"
#include "particles/potentials.hpp"
#include "pipeline/spread_method.hpp"

namespace meshparticles {

namespace {

using V = RunOptionValues;

RunOptionSpec whole(const std::string& name, WholeField field, WholeRange range, const std::string& help) {
  return {name, name, field, help, range};
}

RunOptionSpec positive(const std::string& name, PositiveField field, const std::string& help) {
  return {name, name, field, help};
}

RunOptionSpec word(const std::string& name, WordField field, std::vector<std::string> words, const std::string& help) {
  return {name, name, field, help, {}, std::move(words)};
}

RunOptionSpec path(const std::string& name, PathField field, const std::string& help) { return {name, name, field, help}; }

RunOptionSpec flag(const std::string& name, FlagField field, const std::string& help) { return {name, name, field, help}; }

RunOptionSpec shown_default(RunOptionSpec row, std::string shown) {
  row.shown_default = std::move(shown);
  return row;
}

std::string backends_help() {
  std::string help;
  for (const BackendDescriptor* backend : backend_table()) {
    help += (help.empty() ? "" : "; ") + backend->name + ": " + backend->summary;
  }
  return help;
}

std::string potentials_help() {
  std::string help;
  for (const PotentialSpec& spec : potential_table()) help += (help.empty() ? "" : "; ") + spec.name + ": " + spec.weight;
  return help;
}

std::vector<RunOptionSpec> declared_options() {
  const RunRequest defaults;
  RunOptionSpec particles = shown_default(whole("particles", &V::particles, kParticleRange,
                                                "Number of particles, at most the mesh's vertices"),
                                          std::to_string(defaults.particles));
  particles.keyword = "n";
  particles.short_name = "n";
  RunOptionSpec quiet = flag("quiet", &V::quiet, "No progress or warnings on stderr");
  quiet.short_name = "q";
  RunOptionSpec strict = flag("strict", &V::strict,
                              "Refuse non-manifold edges and vertices and repeated triangles (default: keep them, "
                              "with a warning)");
  strict.keyword.clear();  // read_mesh(strict=) in Python: the mesh is read before run()
  std::vector<RunOptionSpec> table = {
      particles,
      word("method", &V::method, {"spread", "paper"},
           "spread: farthest-point optimization on the surface with its long edges split, the "
           "evenest spacing (default); paper: the paper's energy and one-ring moves on the mesh's vertices "
           "(implied by --backend, --scheme, --colors, --weights, --rebuild-every, --wg, --tile or --init v0)"),
      positive("vertices-per-particle", &V::vertices_per_particle,
               "spread: refine the whole mesh by midpoint rounds until it has this many vertices per particle "
               "(default: none, only edges over " + format_number("%g", kSpreadLongestEdge) +
                   " spacings split; more spreads a little further at a larger cost)"),
      whole("relax-rounds", &V::relax_rounds, kRelaxRoundRange,
            "spread: at most this many rounds pushing all particles apart at once, off the vertices, after the "
            "sweeps (default " + std::to_string(kSpreadRelaxRounds) +
                "); where that is not kept, an evening step moves them one by one; 0: neither, the sweeps' vertices"),
      shown_default(whole("iterations", &V::iterations, kRunIterationRange,
                          "Stop after this many iterations (spread: sweeps), or when nothing moves; 0 writes the start "
                          "and its quality"),
                    std::to_string(defaults.max_iterations)),
      shown_default(word("backend", &V::backend, backend_names(), backends_help()),
                    "field on a dense table, serial-field on local distances"),  // plan_run's rule
      word("scheme", &V::scheme, {"sequential", "synchronous", "colored", "monotone"},
           "sequential, synchronous, colored or monotone (colored, with every iteration lowering the energy; "
           "default: sequential on serial and serial-field, monotone on the OpenCL backends)"),
      whole("colors", &V::colors, kColorRange,
            "Groups of the colored and monotone schemes (default " + std::to_string(kDefaultColors) + ")"),
      shown_default(word("init", &V::init, {"v0", "random", "farthest"},
                         "Start: v0 (all on one vertex), random, farthest (farthest-point sampling)"),
                    init_name(defaults.init)),
      whole("start-vertex", &V::start_vertex, kVertexIdRange, "Input vertex id for v0, or the first farthest sample"),
      shown_default(whole("seed", &V::seed, kSeedRange, "Seed of random and farthest starts"),
                    std::to_string(defaults.seed)),
      positive("sigma", &V::sigma, "Sigma in mesh units (default from the particle spacing, see docs)"),
      shown_default(word("potential", &V::potential, potential_names(), potentials_help()),
                    potential_name(defaults.potential)),
      word("geodesic", &V::geodesic, {"fmm", "fim", "dijkstra"},
           geodesic_solver_help() +
               "; default fmm, or fim where the paper method's default backend gives a GPU the balls of local "
               "distances"),
      shown_default(word("distances", &V::distances, {"dense", "local", "auto"},
                         "dense (the V x V table, cached on disk), local (each vertex's ball within --cutoff, "
                         "computed on demand) or auto (dense up to " + std::to_string(kAutoDenseVertices) +
                             " vertices, when cached, or when the backend needs it; else local)"),
                    store_kind_name(defaults.distances.kind)),
      positive("cutoff", &V::cutoff,
               "Local distances: the balls' radius in hexagonal spacings d_hex (default " +
                   format_number("%g", kDefaultCutoff) + ")"),
      word("device", &V::device, {},
           "OpenCL device: P:D or part of its name (default: $MESHPARTICLES_DEVICE, else the first GPU, else the "
           "first device); with spread, given, its evening's Voronoi diagrams run there, and on a GPU its measurement's "
           "balls (by fim) (default: on the host)"),
      whole("wg", &V::wg, kWorkGroupRange, "Work-group size of the kernel"),
      whole("tile", &V::tile, kTileRange, "Tile size (particles staged in local memory; tiled only)"),
      word("weights", &V::weights, {"float", "half"},
           "Weight table of the field backends: float (float32, default) or half (half the bytes)"),
      whole("rebuild-every", &V::rebuild_every, kRebuildRange,
            "Field backends: rebuild the field from scratch every N iterations (default 0: never; it is exact and "
            "does not drift)"),
      path("tuning-file", &V::tuning_file,
           "Sizes saved by `sweep --save`, used when --wg and --tile are absent (default: "
           "$XDG_CONFIG_HOME/meshparticles/tuning.json)"),
      strict,
      path("cache-dir", &V::cache_dir, "Distance cache directory (default: $XDG_CACHE_HOME/meshparticles)"),
      flag("no-cache", &V::no_cache, "Neither read nor write the distance cache"),
      shown_default(whole("threads", &V::threads, kThreadRange,
                          "Threads for all-pairs distances and spread's evening (0: all cores)"),
                    std::to_string(defaults.distances.geodesics.threads)),
      quiet,
  };
  for (RunOptionSpec& option : table) {
    for (char& c : option.keyword) c = c == '-' ? '_' : c;
  }
  return table;
}

}  // namespace

std::string RunOptionSpec::command_line_names() const {
  return (short_name.empty() ? "" : "-" + short_name + ",") + "--" + name;
}

const std::vector<RunOptionSpec>& run_option_table() {
  static const std::vector<RunOptionSpec> table = declared_options();
  return table;
}

const RunOptionSpec& run_option(const std::string& name) {
  for (const RunOptionSpec& option : run_option_table()) {
    if (option.name == name) return option;
  }
  throw std::logic_error("no run option --" + name);
}

std::string geodesic_solver_help() {
  return "Distance solver: fmm (fast marching), fim (the fast iterative method) or dijkstra (edge graph)";
}

}  // namespace meshparticles
