// `meshparticles model PARTICLES... --out DIR`: a statistical shape model of
// corresponding particle sets (row i the same point on every shape, as
// ShapeWorks writes them): Procrustes alignment, the mean and the modes of
// variation, and the measures shape-model papers report
// (docs/CORRESPONDENCE.md).
#include <cstdio>
#include <memory>

#include "cli/commands.hpp"
#include "common/directory_lock.hpp"
#include "common/text_format.hpp"
#include "common/user_error.hpp"
#include "options/number_options.hpp"
#include "particles/particle_file.hpp"
#include "reports/shape_model_outputs.hpp"

namespace meshparticles {

namespace {

struct ModelOptions {
  std::vector<std::string> particle_files;
  std::string out = "model";
  bool no_scale = false;
  std::size_t samples = 1000;
  std::uint64_t seed = 1;
  bool quiet = false;
};

// A shape smaller than this is refused: the squares of its offsets, which
// Procrustes and the modes sum, underflow (kLargestParticleCoordinate is
// the bound above).
constexpr double kSmallestShapeExtent = 1e-150;

// The files as point sets, refused unless every one has the same points.
std::vector<PointSet> read_shapes(const std::vector<std::string>& files) {
  std::vector<PointSet> shapes;
  for (const std::string& file : files) {
    const std::vector<Vec3> points = read_particle_points(file);
    PointSet shape(Eigen::Index(points.size()), 3);
    for (std::size_t i = 0; i < points.size(); ++i) shape.row(Eigen::Index(i)) << points[i].x, points[i].y, points[i].z;
    if (!shapes.empty() && shape.rows() != shapes.front().rows()) {
      throw UserError(file + ": " + std::to_string(shape.rows()) + " points, but " + files.front() + " has " +
                      std::to_string(shapes.front().rows()) + ": a shape model needs the same points on every shape");
    }
    // Compared exactly: a norm squares the offsets, and those of points
    // 1e-170 apart underflow to 0 (they were said to be at one place).
    const double extent = shape.rows() < 2 ? 0.0 : (shape.rowwise() - shape.row(0)).cwiseAbs().maxCoeff();
    if (extent == 0) throw UserError(file + ": its points are all at one place: no shape to align");
    if (extent < kSmallestShapeExtent) {
      throw UserError(file + ": its points lie within " + format_number("%.3g", extent) +
                      " of each other, under 1e-150 (their squared distances would underflow): scale the coordinates");
    }
    shapes.push_back(std::move(shape));
  }
  return shapes;
}

void run_model(const ModelOptions& options) {
  prepare_shape_model_directory(options.out, options.particle_files);  // before the work
  const DirectoryLock lock(options.out, "model");  // to the last file: a second model there is refused
  const std::vector<PointSet> shapes = read_shapes(options.particle_files);
  const ShapeModel model = build_shape_model(shapes, !options.no_scale, options.samples, options.seed, options.quiet);
  const ShapeModelOutputs outputs{options.particle_files, &model,
                                  {{"scale", !options.no_scale}, {"samples", options.samples}, {"seed", options.seed}}};
  write_shape_model(options.out, outputs);
  const ProcrustesAlignment& alignment = model.alignment;
  const ModelQuality& quality = model.quality;

  std::printf("shapes      %zu, %lld points each\n", shapes.size(), static_cast<long long>(shapes.front().rows()));
  std::printf("alignment   Procrustes%s, %zu rounds%s\n", options.no_scale ? " without scaling" : "",
              alignment.iterations, alignment.converged ? "" : " (not converged)");
  std::printf("modes       %lld", static_cast<long long>(model.modes.variances.size()));
  if (!quality.compactness.empty()) std::printf("; variance held by 1, 3, 5 modes:");
  for (const std::size_t m : {1, 3, 5}) {
    if (m <= quality.compactness.size()) std::printf(" %.1f%%", 100 * quality.compactness[m - 1]);
  }
  std::printf("\n");
  if (model.modes.variances.size() == 0) {
    std::printf("measures    none: after alignment the shapes are one shape (no variance above rounding)\n");
  } else if (!quality.generalization.empty() && !quality.specificity.empty()) {
    std::printf("measures    with 1 mode: generalization %.4g, specificity %.4g (mean point distances)\n",
                quality.generalization.front().mean, quality.specificity.front().mean);
  }
  if (!quality.shapeworks.generalization.empty()) {
    std::printf("shapeworks  with 1 mode: generalization %.4g, specificity %.4g (as ShapeWorks computes them)\n",
                quality.shapeworks.generalization.front(), quality.shapeworks.specificity.front());
  }
  std::printf("output      %s/{mean.particles, modes.csv, modes.json, transforms.json, evaluation.csv, "
              "evaluation_shapeworks.csv, model.json, NNN_NAME.aligned.particles}\n",
              options.out.c_str());
}

}  // namespace

void add_model_command(CLI::App& app) {
  auto options = std::make_shared<ModelOptions>();
  CLI::App* model = app.add_subcommand(
      "model", "A shape model of corresponding particle files: alignment, mean, modes and their measures");
  model->add_option("particles", options->particle_files,
                    "Particle files, one per shape, row i the same point on every shape (.particles)")
      ->required()
      ->expected(2, -1);
  model->add_option("--out", options->out, "Output directory")->capture_default_str();
  model->add_flag("--no-scale", options->no_scale, "Align by rotation and translation only (default: also size)");
  add_whole_number_option(*model, "--samples", options->samples, WholeRange{1, 1000000},
                          "Shapes drawn from the model per number of modes, for specificity");
  add_whole_number_option(*model, "--seed", options->seed, kSeedRange, "Seed of the specificity draws");
  model->add_flag("-q,--quiet", options->quiet, "No progress line");
  model->callback([options] { run_model(*options); });
}

}  // namespace meshparticles
