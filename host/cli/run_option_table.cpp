#include "cli/run_option_table.hpp"

#include <stdexcept>

#include "backends/backend_table.hpp"
#include "particles/potentials.hpp"

namespace meshparticles {

namespace {

RunOptionSpec whole(const std::string& name, WholeRange range) {
  return {name, name, RunOptionKind::whole, range, {}};
}

RunOptionSpec word(const std::string& name, std::vector<std::string> words) {
  return {name, name, RunOptionKind::word, {}, std::move(words)};
}

RunOptionSpec of_kind(const std::string& name, RunOptionKind kind) { return {name, name, kind, {}, {}}; }

std::vector<RunOptionSpec> declared_options() {
  std::vector<RunOptionSpec> table = {
      {"particles", "n", RunOptionKind::whole, kParticleRange, {}},
      word("method", {"spread", "paper"}),
      of_kind("vertices-per-particle", RunOptionKind::positive),
      whole("relax-rounds", kRelaxRoundRange),
      whole("iterations", kRunIterationRange),
      word("backend", backend_names()),
      word("scheme", {"sequential", "synchronous", "colored", "monotone"}),
      whole("colors", kColorRange),
      word("init", {"v0", "random", "farthest"}),
      whole("start-vertex", kVertexIdRange),
      whole("seed", kSeedRange),
      of_kind("sigma", RunOptionKind::positive),
      word("potential", potential_names()),
      word("geodesic", {"fmm", "fim", "dijkstra"}),
      word("distances", {"dense", "local", "auto"}),
      of_kind("cutoff", RunOptionKind::positive),
      word("device", {}),
      whole("wg", kWorkGroupRange),
      whole("tile", kTileRange),
      word("weights", {"float", "half"}),
      whole("rebuild-every", kRebuildRange),
      of_kind("tuning-file", RunOptionKind::path),
      of_kind("cache-dir", RunOptionKind::path),
      of_kind("no-cache", RunOptionKind::flag),
      whole("threads", kThreadRange),
      of_kind("quiet", RunOptionKind::flag),
  };
  for (RunOptionSpec& option : table) {
    for (char& c : option.keyword) c = c == '-' ? '_' : c;
  }
  return table;
}

}  // namespace

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

}  // namespace meshparticles
