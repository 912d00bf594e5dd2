#include "reports/shape_model_outputs.hpp"

#include <cstdio>
#include <set>

#include "common/atomic_directory.hpp"
#include "common/atomic_file.hpp"
#include "common/exact_number.hpp"
#include "common/json_text.hpp"
#include "common/text_format.hpp"
#include "common/version.hpp"

namespace meshparticles {

namespace {

const char* const kFixedFiles[] = {"mean.particles", "modes.csv", "modes.json", "transforms.json",
                                   "evaluation.csv", "evaluation_shapeworks.csv", "model.json"};

std::vector<std::string> aligned_file_names(const std::vector<std::string>& shapes) {
  std::vector<std::string> names = indexed_stems(shapes);
  for (std::string& name : names) name += ".aligned.particles";
  return names;
}

std::set<std::string> all_file_names(const std::vector<std::string>& shapes) {
  std::set<std::string> names(std::begin(kFixedFiles), std::end(kFixedFiles));
  for (const std::string& name : aligned_file_names(shapes)) names.insert(name);
  return names;
}

// Exact coordinates (common/exact_number.hpp): the files read back to the model's points.
void write_point_set(std::ostream& out, const PointSet& points) {
  for (Eigen::Index i = 0; i < points.rows(); ++i) out << exact_triple(points(i, 0), points(i, 1), points(i, 2)) << "\n";
}

nlohmann::json rows_of(const PointSet& points) {
  nlohmann::json rows = nlohmann::json::array();
  for (Eigen::Index i = 0; i < points.rows(); ++i) rows.push_back({points(i, 0), points(i, 1), points(i, 2)});
  return rows;
}

nlohmann::json measures_json(const std::vector<ModelMeasure>& measures) {
  nlohmann::json means = nlohmann::json::array(), sds = nlohmann::json::array();
  for (const ModelMeasure& m : measures) {
    means.push_back(m.mean);
    sds.push_back(m.sd);
  }
  return {{"mean", means}, {"sd", sds}};
}

nlohmann::json shapeworks_json(const ShapeWorksMeasures& measures) {
  return {{"compactness", measures.compactness},
          {"generalization", measures.generalization},
          {"specificity", measures.specificity},
          {"specificity_samples", ShapeWorksMeasures::kSamples}};
}

// The curves as ShapeWorks computes them, one row per M (an empty cell
// where a curve is shorter).
void write_shapeworks_evaluation(std::ostream& out, const ShapeWorksMeasures& measures) {
  out << "modes,compactness,generalization,specificity\n";
  const auto cell = [&](const std::vector<double>& curve, std::size_t m, const char* format) {
    out << "," << (m < curve.size() ? format_number(format, curve[m]) : "");
  };
  for (std::size_t m = 0; m < measures.compactness.size(); ++m) {
    out << m + 1;
    cell(measures.compactness, m, "%.6f");
    cell(measures.generalization, m, "%.9g");
    cell(measures.specificity, m, "%.9g");
    out << "\n";
  }
}

}  // namespace

std::vector<std::string> indexed_stems(const std::vector<std::string>& shapes) {
  std::vector<std::string> stems;
  for (std::size_t s = 0; s < shapes.size(); ++s) {
    char index[24];
    std::snprintf(index, sizeof index, "%03zu_", s);
    stems.push_back(index + std::filesystem::path(shapes[s]).stem().string());
  }
  return stems;
}

void prepare_shape_model_directory(const std::filesystem::path& directory, const std::vector<std::string>& shapes) {
  check_replaceable_directory(directory, all_file_names(shapes));
}

nlohmann::json shape_model_summary(const ShapeModelOutputs& outputs) {
  const ProcrustesAlignment& alignment = outputs.model->alignment;
  const ShapeModes& model = outputs.model->modes;
  nlohmann::json variances = nlohmann::json::array();
  for (Eigen::Index k = 0; k < model.variances.size(); ++k) variances.push_back(model.variances(k));
  return {{"version", program_version()},
          {"params", outputs.params},
          {"shapes", outputs.shapes},
          {"points", model.mean.size() / 3},
          {"procrustes",
           {{"iterations", alignment.iterations}, {"converged", alignment.converged}, {"mean_size", alignment.mean_size}}},
          {"variances", variances},
          {"total_variance", model.total_variance()},
          {"compactness", outputs.model->quality.compactness},
          {"generalization", measures_json(outputs.model->quality.generalization)},
          {"specificity", measures_json(outputs.model->quality.specificity)},
          {"specificity_samples", outputs.model->quality.samples},
          {"shapeworks", shapeworks_json(outputs.model->quality.shapeworks)}};
}

void write_shape_model(const std::filesystem::path& directory, const ShapeModelOutputs& outputs) {
  const ProcrustesAlignment& alignment = outputs.model->alignment;
  const ShapeModes& model = outputs.model->modes;
  const ModelQuality& quality = outputs.model->quality;
  const std::vector<std::string> aligned_names = aligned_file_names(outputs.shapes);
  write_directory_atomically(directory, all_file_names(outputs.shapes), [&](const std::filesystem::path& staging) {
    for (std::size_t s = 0; s < aligned_names.size(); ++s) {
      write_new_file(staging / aligned_names[s],
                     [&](std::ostream& out) { write_point_set(out, alignment.aligned[s]); });
    }
    write_new_file(staging / "mean.particles",
                   [&](std::ostream& out) { write_point_set(out, unflattened(model.mean)); });
    write_new_file(staging / "modes.csv", [&](std::ostream& out) {
      out << "mode,variance,explained,cumulative\n";
      for (Eigen::Index k = 0; k < model.variances.size(); ++k) {
        out << k + 1 << "," << format_number("%.9g", model.variances(k)) << ","
            << format_number("%.6f", model.variances(k) / model.total_variance()) << ","
            << format_number("%.6f", quality.compactness[std::size_t(k)]) << "\n";
      }
    });
    write_new_file(staging / "modes.json", [&](std::ostream& out) {
      nlohmann::json modes = nlohmann::json::array();
      for (Eigen::Index k = 0; k < model.variances.size(); ++k) {
        // Per point, the displacement of one unit of the mode (a standard
        // deviation is sqrt(variance) of it).
        modes.push_back({{"variance", model.variances(k)}, {"vectors", rows_of(unflattened(model.modes.col(k)))}});
      }
      out << json_text({{"mean", rows_of(unflattened(model.mean))}, {"modes", modes}}) << "\n";
    });
    write_new_file(staging / "transforms.json", [&](std::ostream& out) {
      nlohmann::json shapes = nlohmann::json::array();
      for (std::size_t s = 0; s < outputs.shapes.size(); ++s) {
        const Similarity& t = alignment.transforms[s];
        nlohmann::json matrix = nlohmann::json::array();
        const Eigen::Matrix4d m = t.matrix();
        for (int r = 0; r < 4; ++r) matrix.push_back({m(r, 0), m(r, 1), m(r, 2), m(r, 3)});
        shapes.push_back({{"file", outputs.shapes[s]}, {"aligned", aligned_names[s]}, {"scale", t.scale},
                          {"matrix", matrix}});
      }
      out << json_text({{"world_to_aligned", shapes}}, 2) << "\n";
    });
    write_new_file(staging / "evaluation.csv", [&](std::ostream& out) {
      out << "modes,compactness,generalization,generalization_sd,specificity,specificity_sd\n";
      for (std::size_t m = 0; m < quality.compactness.size(); ++m) {
        out << m + 1 << "," << format_number("%.6f", quality.compactness[m]);
        if (m < quality.generalization.size()) {
          out << "," << format_number("%.9g", quality.generalization[m].mean) << ","
              << format_number("%.9g", quality.generalization[m].sd);
        } else {
          out << ",,";
        }
        out << "," << format_number("%.9g", quality.specificity[m].mean) << ","
            << format_number("%.9g", quality.specificity[m].sd) << "\n";
      }
    });
    write_new_file(staging / "evaluation_shapeworks.csv",
                   [&](std::ostream& out) { write_shapeworks_evaluation(out, quality.shapeworks); });
    write_new_file(staging / "model.json", [&](std::ostream& out) { out << json_text(shape_model_summary(outputs), 2) << "\n"; });
  });
}

}  // namespace meshparticles
