#include "quality/particle_set_report.hpp"

#include <algorithm>
#include <cstdio>
#include <functional>
#include <limits>

#include "reports/text_format.hpp"

namespace meshparticles {

MeasuredSet measure_particle_file(const SurfaceMesh& mesh, const DistanceTable& distances, const std::string& path,
                                  const std::vector<Vec3>& points, Potential potential, std::optional<double> sigma) {
  MeasuredSet set;
  set.path = path;
  set.snapped = snap_to_vertices(mesh, points);
  const std::size_t n = set.snapped.positions.size();
  set.energy = {potential, sigma.value_or(default_sigma(potential, mesh.area(), n))};
  set.quality = measure_quality(mesh, distances, set.snapped.positions, set.energy);
  return set;
}

double mean_distance_to_nearest(const DistanceTable& distances, const std::vector<VertexId>& from,
                                const std::vector<VertexId>& to) {
  double sum = 0;
  for (const VertexId a : from) {
    const auto row = distances.row(a);
    float nearest = std::numeric_limits<float>::infinity();
    for (const VertexId b : to) nearest = std::min(nearest, row[b]);
    sum += nearest;
  }
  return from.empty() ? 0.0 : sum / double(from.size());
}

nlohmann::json measured_set_json(const MeasuredSet& set) {
  return {{"particles", set.path},
          {"n", set.snapped.positions.size()},
          {"largest_snap", set.snapped.largest_snap},
          {"largest_snap_particle", set.snapped.largest_snap_particle},
          {"potential", potential_name(set.energy.potential)},
          {"sigma", set.energy.sigma},
          {"quality", quality_json(set.quality)}};
}

std::string quality_table(const std::vector<const MeasuredSet*>& sets) {
  auto cell = [](const std::optional<double>& value, const char* pattern) {
    return value ? format_number(pattern, *value) : std::string("-");
  };
  using Q = const MeasuredSet&;
  const auto fixed = [](double v, const char* pattern) { return format_number(pattern, v); };
  const std::vector<std::pair<std::string, std::function<std::string(Q)>>> rows = {
      {"particles", [](Q s) { return std::to_string(s.snapped.positions.size()); }},
      {"largest snap", [&](Q s) { return fixed(s.snapped.largest_snap, "%.3g"); }},
      {"nn min", [&](Q s) { return cell(s.quality.nn_min, "%.4g"); }},
      {"nn mean", [&](Q s) { return cell(s.quality.nn_mean, "%.4g"); }},
      {"nn std", [&](Q s) { return cell(s.quality.nn_std, "%.4g"); }},
      {"nn cv", [&](Q s) { return cell(s.quality.nn_cv, "%.4f"); }},
      {"d_hex", [&](Q s) { return fixed(s.quality.d_hex, "%.4g"); }},
      {"rho = nn min / d_hex", [&](Q s) { return cell(s.quality.rho, "%.4f"); }},
      {"cover / d_hex", [&](Q s) { return cell(s.quality.cover, "%.4f"); }},
      {"sigma", [&](Q s) { return fixed(s.energy.sigma, "%.4g"); }},
      {"energy", [&](Q s) { return fixed(s.quality.energy, "%.6g"); }},
      {"stacked", [](Q s) { return std::to_string(s.quality.stacked); }},
  };
  std::string text;
  char line[256];
  std::snprintf(line, sizeof line, "%-22s", "");
  text += line;
  for (std::size_t k = 0; k < sets.size(); ++k) {  // "A ...q1/particles.particles": the path's tail
    const std::string& path = sets[k]->path;
    std::string title = path.size() > 22 ? "..." + path.substr(path.size() - 22) : path;
    if (sets.size() > 1) title = std::string(1, char('A' + k)) + " " + title;
    std::snprintf(line, sizeof line, "  %-28s", title.c_str());
    text += line;
  }
  text += "\n";
  for (const auto& [name, value] : rows) {
    std::snprintf(line, sizeof line, "%-22s", name.c_str());
    text += line;
    for (const MeasuredSet* set : sets) {
      std::snprintf(line, sizeof line, "  %-28s", value(*set).c_str());
      text += line;
    }
    text += "\n";
  }
  return text;
}

}  // namespace meshparticles
