#include "reports/quality_report.hpp"

#include <cstdio>
#include <functional>

#include "common/text_format.hpp"

namespace meshparticles {

namespace {

nlohmann::json optional_json(const std::optional<double>& value) {
  return value ? nlohmann::json(*value) : nlohmann::json(nullptr);
}

}  // namespace

nlohmann::json quality_json(const DistributionQuality& quality) {
  return {{"nn_min", optional_json(quality.nn_min)},
          {"nn_mean", optional_json(quality.nn_mean)},
          {"nn_std", optional_json(quality.nn_std)},
          {"nn_cv", optional_json(quality.nn_cv)},
          {"rho", optional_json(quality.rho)},
          {"cover", optional_json(quality.cover)},
          {"energy", quality.energy},
          {"stacked", quality.stacked},
          {"alone", quality.alone},
          {"d_hex", quality.d_hex}};
}

DistributionQuality quality_from_json(const nlohmann::json& json, std::size_t particles) {
  const auto optional = [&](const char* key) {
    return json.at(key).is_null() ? std::nullopt : std::optional<double>(json.at(key).get<double>());
  };
  DistributionQuality quality;
  quality.particles = particles;
  quality.nn_min = optional("nn_min");
  quality.nn_mean = optional("nn_mean");
  quality.nn_std = optional("nn_std");
  quality.nn_cv = optional("nn_cv");
  quality.rho = optional("rho");
  quality.cover = optional("cover");
  quality.energy = json.at("energy").get<double>();
  quality.stacked = json.at("stacked").get<std::size_t>();
  quality.alone = json.at("alone").get<std::size_t>();
  quality.d_hex = json.at("d_hex").get<double>();
  return quality;
}

std::string quality_line(const DistributionQuality& quality) {
  auto text = [](const std::optional<double>& value, const char* pattern) {
    return value ? format_number(pattern, *value) : std::string("-");
  };
  return "nn min " + text(quality.nn_min, "%.4g") + " mean " + text(quality.nn_mean, "%.4g") + " cv " +
         text(quality.nn_cv, "%.3f") + ", rho " + text(quality.rho, "%.3f") + ", cover " +
         text(quality.cover, "%.3f") + ", energy " + format_number("%.6g", quality.energy) + ", " +
         std::to_string(quality.stacked) + " stacked";
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
  // Whole paths on lines of their own (a column would cut them); the
  // columns are headed by their letters when there are two.
  std::string text;
  char line[256];
  if (sets.size() == 1) {
    text += "file  " + sets.front()->path + "\n";
  } else {
    for (std::size_t k = 0; k < sets.size(); ++k) text += std::string(1, char('A' + k)) + "     " + sets[k]->path + "\n";
    std::snprintf(line, sizeof line, "%-22s", "");
    text += line;
    for (std::size_t k = 0; k < sets.size(); ++k) {
      std::snprintf(line, sizeof line, "  %-28c", char('A' + k));
      text += line;
    }
    text += "\n";
  }
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

nlohmann::json point_sets_json(const std::string& mesh_label, const PointSetsMeasurement& measured) {
  nlohmann::json out = {{"mesh", mesh_label},
                        {"refinement", measured.measuring.spread ? "spread" : "uniform"},
                        {"refinement_levels", measured.measuring.refined.levels},
                        {"measured_vertices", measured.measuring.refined.mesh.vertex_count()}};
  if (measured.sets.size() == 2) {
    out["a"] = measured_set_json(measured.sets[0]);
    out["b"] = measured_set_json(measured.sets[1]);
    out["mean_distance_a_to_b"] = *measured.mean_a_to_b;
    out["mean_distance_b_to_a"] = *measured.mean_b_to_a;
  } else {
    out.update(measured_set_json(measured.sets.front()));
  }
  return out;
}

}  // namespace meshparticles
