#include "correspondence/joint_refinement.hpp"

#include <cmath>
#include <cstdio>

#include "common/progress.hpp"
#include "correspondence/point_tree.hpp"
#include "particles/particle_params.hpp"
#include "shape_model/procrustes.hpp"

namespace meshparticles {

namespace {

// Neighbours looked at by the sampling step: a hexagonal packing has 6
// within the spacing; a crowded place a few more.
constexpr std::size_t kNeighbours = 10;
// A step is at most this share of the shape's spacing: no particle jumps
// over a neighbour, and the walk stays short.
constexpr double kLargestStep = 0.3;
// The ensemble entropy's regulariser, per particle, in spacings: variation
// that moves particles by much less than this between shapes is shrunk
// (noise, a correspondence slipping), by much more is kept (a mode). At a
// tenth of a spacing, the part of a nonlinear mode that the linear modes
// miss (a bump growing) was shrunk too, pulling particles down the bump's
// sides: holes at its tip (cover 1.56 at n = 1,024).
constexpr double kShapeNoise = 0.05;
// Each particle of a pair closer than the spacing moves away by this share of
// the overlap: a quarter, not a half, because a crowded particle is pushed by
// several neighbours at once, and half each overshoots into a jostle (nn_cv
// 0.040 against 0.022 at n = 256 on the ellipsoid population).
constexpr double kPush = 0.25;
// How much of the shrinkable variation one iteration removes.
constexpr double kShrinkRate = 0.5;

PointSet positions(const ShapeParticles& shape) {
  PointSet points(Eigen::Index(shape.at.size()), 3);
  for (std::size_t i = 0; i < shape.at.size(); ++i) {
    points.row(Eigen::Index(i)) << shape.at[i].at.x, shape.at[i].at.y, shape.at[i].at.z;
  }
  return points;
}

// Soft disks of diameter `spacing`: each pair closer than that is pushed
// apart, each by kPush of its overlap. Adds the mean overlap (in spacings) to `overlap`.
PointSet sampling_step(const PointSet& points, double spacing, double& overlap) {
  PointSet step = PointSet::Zero(points.rows(), 3);
  const PointTree tree(points);
  double total = 0;
  for (Eigen::Index i = 0; i < points.rows(); ++i) {
    for (const Eigen::Index j : tree.nearest(points.row(i), kNeighbours)) {
      if (j == i) continue;
      const Eigen::RowVector3d apart = points.row(i) - points.row(j);
      const double distance = apart.norm();
      if (distance >= spacing || distance == 0) continue;
      step.row(i) += kPush * (spacing - distance) / distance * apart;
      total += (spacing - distance) / spacing;
    }
  }
  overlap += total / double(points.rows());
  return step;
}

// Per shape, the step (in its own coordinates) down the gradient of
// log det(C + alpha I), C the covariance of the aligned shapes: with Y the
// centred shapes as columns, (Y Y^T / S + alpha I)^-1 y_k = Y (Y^T Y / S +
// alpha I)^-1 e_k (S x S, ShapeWorks' dual form). Along a mode of variance
// lambda a shape moves back by rate alpha / (lambda + alpha) of its part.
std::vector<PointSet> correspondence_steps(const std::vector<PointSet>& shapes, double aligned_spacing,
                                           double& mean_step) {
  const ProcrustesAlignment alignment = align_procrustes(shapes, true);
  const Eigen::Index count = Eigen::Index(shapes.size());
  const Eigen::Index length = shapes.front().rows() * 3;
  Eigen::MatrixXd centred(length, count);
  for (Eigen::Index k = 0; k < count; ++k) centred.col(k) = flattened(alignment.aligned[std::size_t(k)]);
  const Eigen::VectorXd mean = centred.rowwise().mean();
  centred.colwise() -= mean;
  const double particles = double(shapes.front().rows());
  const double alpha = particles * std::pow(kShapeNoise * aligned_spacing, 2);
  const Eigen::MatrixXd gram = centred.transpose() * centred / double(count) +
                               alpha * Eigen::MatrixXd::Identity(count, count);
  const Eigen::MatrixXd pulled = centred * gram.ldlt().solve(Eigen::MatrixXd::Identity(count, count));
  std::vector<PointSet> steps;
  double total = 0;
  for (Eigen::Index k = 0; k < count; ++k) {
    const Similarity& to_common = alignment.transforms[std::size_t(k)];
    const PointSet aligned_step = unflattened(-kShrinkRate * alpha * pulled.col(k));
    total += aligned_step.rowwise().norm().mean();
    // Back into the shape's own coordinates: turned back, unscaled.
    steps.push_back(aligned_step * to_common.rotation / to_common.scale);
  }
  mean_step += total / double(count) / aligned_spacing;
  return steps;
}

double centroid_size(const PointSet& points) {
  const Eigen::RowVector3d centre = points.colwise().mean();
  return std::sqrt((points.rowwise() - centre).squaredNorm());
}

// The spacing in the aligned frame, where Procrustes scales every shape to
// the shapes' mean centroid size: each shape's spacing at that size, averaged.
double aligned_spacing(const std::vector<PointSet>& shapes, const std::vector<double>& spacings) {
  std::vector<double> sizes;
  for (const PointSet& shape : shapes) sizes.push_back(centroid_size(shape));
  double mean_size = 0;
  for (const double size : sizes) mean_size += size / double(sizes.size());
  double spacing = 0;
  for (std::size_t k = 0; k < shapes.size(); ++k) spacing += spacings[k] * mean_size / sizes[k] / double(shapes.size());
  return spacing;
}

}  // namespace

JointRefinementRecord refine_jointly(std::vector<ShapeParticles>& shapes, const JointRefinementOptions& options,
                                     bool quiet) {
  JointRefinementRecord record;
  if (shapes.size() < 2 || options.iterations == 0) return record;
  const std::size_t particles = shapes.front().at.size();
  std::vector<SurfaceWalk> walks;
  std::vector<double> spacings;
  for (const ShapeParticles& shape : shapes) {
    walks.emplace_back(*shape.mesh);
    spacings.push_back(hexagonal_spacing(shape.mesh->area(), particles));
  }
  ProgressLine progress("refine", options.iterations, quiet);
  for (std::size_t iteration = 0; iteration < options.iterations; ++iteration) {
    std::vector<PointSet> points;
    for (const ShapeParticles& shape : shapes) points.push_back(positions(shape));
    const double aligned = aligned_spacing(points, spacings);
    double mean_step = 0, overlap = 0;
    const std::vector<PointSet> pulls = options.correspondence_weight > 0
                                            ? correspondence_steps(points, aligned, mean_step)
                                            : std::vector<PointSet>(shapes.size(), PointSet::Zero(Eigen::Index(particles), 3));
    for (std::size_t k = 0; k < shapes.size(); ++k) {
      const PointSet push = sampling_step(points[k], spacings[k], overlap);
      for (std::size_t i = 0; i < particles; ++i) {
        SurfaceLocation& at = shapes[k].at[i];
        const Eigen::RowVector3d total = push.row(Eigen::Index(i)) + options.correspondence_weight * pulls[k].row(Eigen::Index(i));
        Vec3 move{total(0), total(1), total(2)};
        const Vec3 normal = walks[k].normal(at.triangle);
        move = move + (-dot(move, normal)) * normal;  // along the surface
        const double length = norm(move), largest = kLargestStep * spacings[k];
        if (length > largest) move = (largest / length) * move;
        if (length > 0) at = walks[k].walk(at.triangle, at.at + move);
      }
    }
    record.overlap.push_back(overlap / double(shapes.size()));
    record.correspondence_step.push_back(mean_step);
    char detail[80];
    std::snprintf(detail, sizeof detail, "overlap %.4f, correspondence step %.4f", record.overlap.back(),
                  record.correspondence_step.back());
    progress.update(iteration + 1, detail);
  }
  progress.finish();
  return record;
}

}  // namespace meshparticles
