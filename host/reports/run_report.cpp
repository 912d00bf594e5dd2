#include "reports/run_report.hpp"

#include <algorithm>

#include "common/version.hpp"
#include "mesh/coincident_sheets.hpp"
#include "pipeline/spread_method.hpp"
#include "reports/quality_report.hpp"

namespace meshparticles {

namespace {

// spread's parameters: its sweeps, working mesh and relaxation.
void add_spread_parameters(const RunPlan& plan, const SpreadPlan& spread, nlohmann::json& params) {
  params["sweeps"] = plan.request.max_iterations;
  params["vertices_per_particle"] = spread.vertices_per_particle;
  params["relax_rounds"] = plan.request.relax_rounds.value_or(kSpreadRelaxRounds);
  // Where the evening's diagrams go if it runs (evening.diagrams: where they went).
  params["evening_diagrams"] = spread.evening_device ? "device" : "host";
  if (spread.evening_device) params["evening_device"] = spread.evening_device->name;
  // Where the evening's moves' cavity centres go (evening.centres: where they went).
  params["evening_centres"] = spread.evening_centres_on_device ? "device" : "host";
  // Where the measurement's balls go (distances.balls_on_device: how many went).
  params["measurement_balls"] = spread.measurement_device ? "device" : "host";
  if (spread.measurement_device) params["measurement_device"] = spread.measurement_device->name;
  // Why they are where they are: --device, or the default's reason.
  params["device_from"] = spread.evening_device ? "--device" : kSpreadHostByDefault;
}

// paper's parameters: its iterations and the backend as decided, with its sizes.
void add_paper_parameters(const RunPlan& plan, const PaperPlan& paper, nlohmann::json& params) {
  params["iterations"] = plan.request.max_iterations;
  params["backend"] = paper.backend.name();
  params["backend_from"] = paper.backend_from;
  params["scheme"] = scheme_name(paper.scheme);
  if (uses_colors(paper.scheme)) params["colors"] = paper.colors;
  if (paper.backend.descriptor->field_method) {
    params["weights"] = weight_format_name(paper.backend.weights);
    params["rebuild_every"] = paper.backend.rebuild_every;
  }
  if (const auto& kernel = paper.backend.kernel) {
    params["wg"] = kernel->work_group_size;
    if (kernel->spec().takes_tile) params["tile"] = kernel->tile_size;
    params["sizes_from"] = paper.backend.sizes_from;
    if (!paper.backend.sizes_note.empty()) params["sizes_note"] = paper.backend.sizes_note;
  }
}

}  // namespace

nlohmann::json run_parameters(const RunPlan& plan, const std::filesystem::path& out) {
  const RunRequest& request = plan.request;
  nlohmann::json params = {{"n", request.particles},
                           {"method", method_option_name(plan.method)},
                           {"method_from", plan.method_from},
                           {"init", init_name(request.init)},
                           {"seed", request.seed},
                           {"sigma", plan.energy.sigma},
                           {"sigma_from", request.sigma ? "--sigma" : "default rule"},
                           {"potential", potential_name(plan.energy.potential)},
                           {"geodesic", method_name(plan.geodesics.method)},
                           {"out", out.string()}};
  if (request.start_vertex) params["start_vertex"] = *request.start_vertex;
  switch (plan.method) {
    case Method::spread: add_spread_parameters(plan, *plan.spread, params); break;
    case Method::paper: add_paper_parameters(plan, *plan.paper, params); break;
  }
  return params;
}

namespace {

// The store and what it cost: where the table came from, or the balls the
// local store computed during the run.
nlohmann::json distances_json(const RunResult& result) {
  const DistancesUsed& used = result.distances;
  nlohmann::json distances = {{"store", store_kind_name(used.kind)}};
  if (used.kind == StoreKind::dense) {
    distances["from_cache"] = used.table_source.from_cache;
    return distances;
  }
  const auto& balls = used.balls;
  distances["cutoff"] = result.plan.cutoff;
  distances["radius"] = result.plan.distances.radius;
  distances["balls_computed"] = balls.balls_computed;
  distances["balls_on_device"] = balls.balls_on_device;  // fim on a device: --geodesic fim, spread's --device
  distances["mean_ball_size"] =
      balls.balls_computed ? double(balls.entries_computed) / double(balls.balls_computed) : 0.0;
  distances["ball_seconds"] = balls.seconds;
  distances["ball_seconds_background"] = balls.background_seconds;
  distances["balls_evicted"] = balls.balls_evicted;
  distances["peak_ball_bytes"] = balls.peak_bytes;
  return distances;
}


nlohmann::json mesh_json(const SurfaceMesh& mesh, const RunResult& result,
                         const std::optional<std::string>& mesh_sha256) {
  const CoincidentSheets sheets = coincident_sheets(mesh);
  nlohmann::json json = {{"path", result.plan.request.mesh_label},
                         {"vertices", mesh.vertex_count()},
                         {"faces", mesh.triangle_count()},
                         {"area", mesh.area()},
                         {"coincident_triangles", sheets.triangles},
                         {"sha256", mesh_sha256 ? nlohmann::json(*mesh_sha256) : nlohmann::json(nullptr)}};
  // Why `quality` of the particle file cannot give this report's figures.
  if (sheets.triangles > 0) json["warnings"] = {coincident_sheets_text(sheets)};
  return json;
}

nlohmann::json seconds_json(const RunTimes& seconds) {
  return {{"geodesics", seconds.geodesics},
          {"particles", seconds.particles},
          {"quality", seconds.quality},
          {"total", seconds.total}};
}

// Sweeps of farthest-point optimization, spacings in hexagonal spacings.
nlohmann::json sweeps_json(const std::vector<SweepRecord>& sweeps, double d_hex) {
  nlohmann::json records = nlohmann::json::array();
  for (const SweepRecord& sweep : sweeps) {
    records.push_back({{"visited", sweep.visited},
                       {"moved", sweep.moved},
                       {"ms", sweep.ms},
                       {"min_spacing", sweep.min_spacing / d_hex},
                       {"mean_spacing", sweep.mean_spacing / d_hex}});
  }
  return records;
}

// spread's evening step: its sweeps, in hexagonal spacings.
nlohmann::json evening_json(const EveningOutcome& evening, double d_hex) {
  nlohmann::json sweeps = nlohmann::json::array();
  std::size_t moved = 0;
  for (const EveningSweep& sweep : evening.sweeps) {
    moved += sweep.moved;
    sweeps.push_back({{"moved", sweep.moved},
                      {"drawn", sweep.drawn},
                      {"smallest_spacing", sweep.smallest / d_hex},
                      {"mean_spacing", sweep.mean / d_hex},
                      {"cover_before", sweep.cover / d_hex},
                      {"longest_move", sweep.longest / d_hex},
                      {"ms", sweep.ms}});
  }
  const EveningDiagrams& diagrams = evening.diagrams;
  nlohmann::json where = {{"on", diagrams.device.empty() ? "host" : "device"},
                          {"count", diagrams.count},
                          {"seconds", diagrams.seconds}};
  if (!diagrams.device.empty()) {
    where["device"] = diagrams.device;
    where["rounds"] = diagrams.rounds;
  }
  nlohmann::json centres = {{"on", evening.moves.device.empty() ? "host" : "device"},
                             {"seconds", evening.moves.seconds}};
  if (!evening.moves.device.empty()) {
    centres["device"] = evening.moves.device;
    centres["launches"] = evening.moves.launches;
    centres["sets_on_host"] = evening.moves.sets_on_host;
    centres["device_seconds"] = evening.moves.device_seconds;
  }
  nlohmann::json swaps = nlohmann::json::array();
  for (const EveningSwap& swap : evening.swaps) {
    swaps.push_back({{"particle", swap.particle},
                     {"smallest_spacing", swap.smallest / d_hex},
                     {"cover", swap.cover / d_hex},
                     {"sweeps", swap.sweeps},
                     {"ms", swap.ms},
                     {"kept", swap.kept}});
  }
  return {{"moves", moved},
          {"cover", evening.cover / d_hex},
          {"kept_sweep", evening.kept_sweep},
          {"diagrams", where},
          {"centres", centres},
          {"sweeps", sweeps},
          {"swaps", swaps}};
}

// The figures both methods' reports share, from its iterations or sweeps.
nlohmann::json figures_json(const IterationFigures& figures) {
  nlohmann::json json = {{"iterations_run", figures.iterations_run},
                         {"stopped", figures.stopped},
                         {"final_energy", figures.final_energy},
                         {"avg_iteration_ms", figures.avg_iteration_ms}};
  if (figures.initial_energy) json["initial_energy"] = *figures.initial_energy;
  if (figures.avg_kernel_ms) json["avg_kernel_ms"] = *figures.avg_kernel_ms;
  return json;
}

// spread: the sweeps of farthest-point optimization in place of the
// energy trace, and the working mesh.
nlohmann::json spread_report(const SurfaceMesh& mesh, const RunResult& result, const SpreadDetails& spread,
                             const std::filesystem::path& out, const std::optional<std::string>& mesh_sha256) {
  const double d_hex = result.quality.d_hex;
  const SurfaceMesh& working = spread.working->mesh;
  const WorkingMeshPlan& planned = result.plan.spread->working_mesh;
  nlohmann::json report = {
      {"version", program_version()},
      {"mesh", mesh_json(mesh, result, mesh_sha256)},
      {"working_mesh", {{"refinement_rounds", spread.working->levels},
                        {"longest_edge", planned.longest_edge},
                        {"vertices", working.vertex_count()},
                        {"faces", working.triangle_count()},
                        {"vertices_per_particle", double(working.vertex_count()) / double(result.plan.request.particles)},
                        {"vertex_cap", planned.max_vertices},
                        {"vertex_cap_set_by", planned.cap_set_by_memory.empty()
                                                  ? "the vertex limit"
                                                  : "memory: half of what may be used, set by " + planned.cap_set_by_memory},
                        {"cut_short", spread.working_mesh_cut_short}}},
      {"params", run_parameters(result.plan, out)},
      {"device", result.device},
      {"distances", distances_json(result)},
      {iteration_records_key(Method::spread), sweeps_json(spread.sweeps, d_hex)}};
  report.update(figures_json(iteration_figures(result)));
  const RelaxationOutcome& relaxation = spread.relaxation;
  const bool relaxed = relaxation.kept < relaxation.candidates.size();
  nlohmann::json round_spacings = nlohmann::json::array();
  for (const double spacing : relaxation.round_spacings) round_spacings.push_back(spacing / d_hex);
  report["relaxation"] = {{"rounds", relaxation.round_spacings.size()},
                          {"ms", relaxation.ms},
                          {"start_spacing", relaxation.start_spacing / d_hex},
                          {"start_cover", relaxation.start_cover / d_hex},
                          {"kept_round", relaxed ? relaxation.candidates[relaxation.kept].round : 0},
                          {"spacing", relaxed ? relaxation.candidates[relaxation.kept].spacing / d_hex
                                              : relaxation.start_spacing / d_hex},
                          {"passed_over_for_cover", relaxation.passed_over_for_cover},
                          {"undone_for_spacing", relaxation.undone_for_spacing},
                          {"skipped_for_straight", relaxation.skipped_for_straight},
                          {"stopped", relaxation_stop_name(relaxation.stopped)},
                          {"spacing_per_round", round_spacings}};
  report["cover_limit"] = spread.cover_limit / d_hex;
  if (spread.evening) report["evening"] = evening_json(*spread.evening, d_hex);
  report["quality"] = quality_json(result.quality);
  report["seconds"] = seconds_json(result.seconds);
  return report;
}

// paper: the energy trace of its iterations, and what they asked of the device.
nlohmann::json paper_report(const SurfaceMesh& mesh, const RunResult& result, const std::filesystem::path& out,
                            const std::optional<std::string>& mesh_sha256) {
  const RunOutcome& outcome = result.outcome;
  nlohmann::json trace = nlohmann::json::array();
  for (const auto& record : outcome.trace) {
    nlohmann::json entry = {{"energy", record.energy}, {"moved", record.moved}, {"ms", record.ms}};
    if (!record.redone_as.empty()) entry["redone_as"] = record.redone_as;
    if (record.balls_solved) entry["balls"] = *record.balls_solved;
    if (record.ball_ms) entry["ball_ms"] = *record.ball_ms;
    if (record.kernel_ms) entry["kernel_ms"] = *record.kernel_ms;
    trace.push_back(entry);
  }
  nlohmann::json report = {
      {"version", program_version()},
      {"mesh", mesh_json(mesh, result, mesh_sha256)},
      {"params", run_parameters(result.plan, out)},
      {"device", result.device},
      {"distances", distances_json(result)},
      {iteration_records_key(Method::paper), trace}};
  report.update(figures_json(iteration_figures(result)));
  if (outcome.traffic) {
    // What the iterations asked of the device; one launch and one wait can
    // cover many iterations (field_iterations).
    const double iterations = double(std::max<std::size_t>(1, outcome.trace.size()));
    report["device_traffic"] = {{"launches", outcome.traffic->launches},
                                {"host_waits", outcome.traffic->host_waits},
                                {"launches_per_iteration", double(outcome.traffic->launches) / iterations},
                                {"host_waits_per_iteration", double(outcome.traffic->host_waits) / iterations}};
  }
  report["quality"] = quality_json(result.quality);
  report["seconds"] = seconds_json(result.seconds);
  return report;
}

}  // namespace

const char* iteration_records_key(Method method) {
  switch (method) {
    case Method::spread: return "sweeps";
    case Method::paper: return "trace";
  }
  return "";
}

IterationFigures iteration_figures(const RunResult& result) {
  IterationFigures figures;
  switch (result.plan.method) {
    case Method::spread: {
      const SpreadDetails& spread = *result.spread;
      double ms_sum = 0;
      for (const SweepRecord& sweep : spread.sweeps) ms_sum += sweep.ms;
      figures.iterations_run = spread.sweeps.size();
      figures.stopped = spread.stopped;
      figures.final_energy = result.quality.energy;
      figures.avg_iteration_ms = spread.sweeps.empty() ? 0.0 : ms_sum / double(spread.sweeps.size());
      break;
    }
    case Method::paper: {
      const RunOutcome& outcome = result.outcome;
      double ms_sum = 0, kernel_ms_sum = 0;
      bool has_kernel_times = false;
      for (const IterationRecord& record : outcome.trace) {
        ms_sum += record.ms;
        if (record.kernel_ms) {
          kernel_ms_sum += *record.kernel_ms;
          has_kernel_times = true;
        }
      }
      figures.iterations_run = outcome.trace.size();
      figures.stopped = outcome.converged ? "converged" : "max_iterations";
      figures.initial_energy = outcome.initial_energy;
      figures.final_energy = outcome.trace.empty() ? outcome.initial_energy : outcome.trace.back().energy;
      figures.avg_iteration_ms = outcome.trace.empty() ? 0.0 : ms_sum / double(outcome.trace.size());
      if (has_kernel_times) figures.avg_kernel_ms = kernel_ms_sum / double(outcome.trace.size());
      break;
    }
  }
  return figures;
}

nlohmann::json run_report(const SurfaceMesh& mesh, const RunResult& result, const std::filesystem::path& out,
                          const std::optional<std::string>& mesh_sha256) {
  switch (result.plan.method) {
    case Method::spread: return spread_report(mesh, result, *result.spread, out, mesh_sha256);
    case Method::paper: return paper_report(mesh, result, out, mesh_sha256);
  }
  return {};
}

}  // namespace meshparticles
