// `meshparticles bench`: the paper's Tables 1 and 2 on the committed meshes,
// our rows beside the paper's figures (measurement/bench.hpp); with
// --quality, how even each placement is (measurement/quality_bench.hpp).
#include <iostream>
#include <set>

#include "backends/backend_table.hpp"
#include "backends/direct_sum_backend.hpp"
#include "backends/field_backend.hpp"
#include "backends/serial_backend.hpp"
#include "cli/commands.hpp"
#include "common/atomic_file.hpp"
#include "common/json_text.hpp"
#include "common/user_error.hpp"
#include "measurement/bench.hpp"
#include "measurement/quality_bench.hpp"
#include "options/number_options.hpp"
#include "options/option_values.hpp"
#include "particles/particle_run.hpp"
#include "reports/bench_report.hpp"
#include "reports/quality_bench_report.hpp"
#include "tuning/tuning_store.hpp"

namespace meshparticles {

namespace {

struct BenchOptions {
  std::vector<std::string> cases;  // "mesh:n"; default: the paper's
  // The paper's three (the serial reference, naive, tiled) and ours.
  std::vector<std::string> backends = {serial_backend().name, naive_backend().name, tiled_backend().name,
                                       field_backend().name};
  BenchSettings settings;
  std::string scheme = "monotone";
  std::string device;
  std::string meshes_dir = "meshes";
  std::string csv;
  std::string json;
  std::string tuning_file;
  bool quality = false;
  DistanceTableOptions table;
};

std::vector<CaseRequest> requested_cases(const BenchOptions& options) {
  if (options.cases.empty()) return options.quality ? quality_cases() : paper_cases();
  std::vector<CaseRequest> cases;
  for (const std::string& text : options.cases) {
    const auto colon = text.find(':');
    if (colon == 0 || colon == std::string::npos) {
      throw UserError("--case '" + text + "': expected MESH:N, e.g. sphere:1024");
    }
    const std::size_t particles = parse_whole_number(text.substr(colon + 1), "--case " + text, kParticleRange);
    cases.push_back({text.substr(0, colon), particles});
  }
  return cases;
}

void write_json(const std::string& file, const nlohmann::json& document) {
  if (!file.empty()) write_file_atomically(file, [&](std::ostream& out) { out << json_text(document, 2) << "\n"; });
}

// As `run` does: an unreadable or unusable tuning file is named, once.
void warn_about_refused_tuning(const BenchPlan& plan, bool quiet) {
  std::set<std::string> notes;
  for (const PlannedCase& planned : plan.cases) {
    for (const CheckedBackend& backend : planned.backends) {
      if (backend.tuning_refused) notes.insert(backend.sizes_note);
    }
  }
  if (quiet) return;
  for (const std::string& note : notes) std::cerr << "meshparticles: warning: " << note << "; using the built-in sizes\n";
}

void run_bench_command(BenchOptions options, bool colors_given) {
  BenchSettings& settings = options.settings;
  settings.device_scheme = parse_scheme(options.scheme);
  if (colors_given && !uses_colors(settings.device_scheme)) {
    throw UserError("--colors applies to --scheme colored and monotone, not " + options.scheme);
  }
  if (options.quality && !options.csv.empty()) throw UserError("--csv applies to the timing tables (with --quality, use --json)");
  for (const auto& file : {options.csv, options.json}) {
    if (!file.empty()) check_writable(file);
  }
  BenchRequest request;
  request.cases = requested_cases(options);
  request.backends = options.backends;
  request.device = options.device;
  request.meshes_dir = options.meshes_dir;
  request.tuning_file = tuning_file_or_default(options.tuning_file);
  request.geodesics = options.table.request(GeodesicMethod::fast_marching);
  request.quiet = options.table.quiet;
  const BenchPlan plan = plan_bench(request);
  warn_about_refused_tuning(plan, options.table.quiet);

  if (options.quality) {
    const std::vector<QualityCase> cases = run_quality_bench(plan, kDefaultMaxIterations);
    std::cout << quality_tables(cases);
    write_json(options.json, quality_bench_json(cases));
    return;
  }
  const std::vector<BenchCase> cases = run_bench(plan, settings);
  std::cout << bench_tables(plan.device_name, settings, cases);
  if (!options.csv.empty()) write_bench_csv(options.csv, plan.device_name, settings, cases);
  write_json(options.json, bench_json(plan.device_name, settings, cases));
}

}  // namespace

void add_bench_command(CLI::App& app) {
  auto options = std::make_shared<BenchOptions>();
  CLI::App* bench = app.add_subcommand(
      "bench", "The paper's Tables 1 and 2: time per iteration of serial, naive, tiled and field beside the paper's");
  add_name_list_option(*bench, "--case", options->cases, {},
                       "MESH:N, comma-separated (default: the paper's sphere 128..1024, torus 128..512, "
                       "atrium 256..1024)")
      ->type_name("MESH:N,...");
  add_name_list_option(*bench, "--backend", options->backends, backend_names(), "Rows, comma-separated");
  add_whole_number_option(*bench, "--iterations", options->settings.iterations, kTimedIterationRange,
                          "Timed iterations per row (the paper: 1000)");
  bench->add_option("--scheme", options->scheme, "Scheme of the device rows: monotone, colored or synchronous")
      ->check(CLI::IsMember({"synchronous", "colored", "monotone"}))
      ->capture_default_str();
  add_whole_number_option(*bench, "--colors", options->settings.colors, kColorRange, "Groups of the colored scheme");
  add_device_option(*bench, options->device);
  bench->add_option("--meshes-dir", options->meshes_dir, "Where the committed meshes are")
      ->check(CLI::ExistingDirectory)
      ->capture_default_str();
  bench->add_option("--csv", options->csv, "Also write the rows as CSV to this file");
  bench->add_option("--json", options->json, "Also write the rows as JSON to this file");
  bench->add_flag("--quality", options->quality,
                  "Instead of timing: the quality of random, farthest-point, the paper's start with its sequential "
                  "loop, and the default run on each backend (default cases: sphere:1024, torus:512, atrium:1024, "
                  "patch:100)");
  bench->add_option("--tuning-file", options->tuning_file,
                    "Sizes saved by `sweep --save` (default: $XDG_CONFIG_HOME/meshparticles/tuning.json)");
  add_distance_table_options(*bench, options->table);
  bench->callback([options, bench] { run_bench_command(*options, bench->count("--colors") > 0); });
}

}  // namespace meshparticles
