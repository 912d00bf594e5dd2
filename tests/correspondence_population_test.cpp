// The test populations of issue 31 and the template's deformation onto a
// shape: an ellipsoid shape's vertices lie exactly where its parameters say
// (the known correspondence is only as good as that), its shapes are meshed
// each on its own, and the deformation follows a stretched shape where
// nearest points cannot.
#include <gtest/gtest.h>

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <limits>
#include <numbers>
#include <random>
#include <set>
#include <vector>

#include "common/random.hpp"
#include "correspondence/ellipsoid_body.hpp"
#include "correspondence/joint_refinement.hpp"
#include "correspondence/mesh_alignment.hpp"
#include "correspondence/population_correspondence.hpp"
#include "correspondence/pose_consensus.hpp"
#include "correspondence/template_deformation.hpp"
#include "fixtures/bent_body.hpp"
#include "fixtures/mesh_generator.hpp"
#include "mesh/mesh_writer.hpp"
#include "mesh/point_cloud_tree.hpp"
#include "particles/particle_params.hpp"
#include "pipeline/run_pipeline.hpp"
#include "shape_model/shape_model.hpp"

namespace meshparticles::testing {
namespace {

double bump_term(const EllipsoidBump& bump, Vec3 u) { return std::exp(-(1 - dot(u, bump.direction)) / bump.width); }

// The parameter of an unposed surface point, as population.json says.
Vec3 parameter_of(const EllipsoidVariant& shape, Vec3 unposed) {
  return normalized({unposed.x / shape.axes.x, unposed.y / shape.axes.y, unposed.z / shape.axes.z});
}

TEST(EllipsoidPopulation, EveryVertexLiesOnItsShapeAtItsParameter) {
  const EllipsoidVariant shape = generate_ellipsoid_variant(7, 1500);
  double worst = 0;
  for (const Vec3& world : shape.mesh.positions()) {
    const Vec3 unposed = shape.pose.unposed(world);
    const Vec3 u = parameter_of(shape, unposed);
    const double r = 1 + shape.bump_height * bump_term(kEllipsoidBump, u) + kEllipsoidKnob.height * bump_term(kEllipsoidKnob, u);
    const Vec3 on_surface = r * Vec3{shape.axes.x * u.x, shape.axes.y * u.y, shape.axes.z * u.z};
    worst = std::max(worst, norm(on_surface + (-1.0) * unposed));
  }
  EXPECT_LT(worst, 1e-12);
  EXPECT_GE(shape.bump_height, 0.1);
  EXPECT_LE(shape.bump_height, 0.6);
  EXPECT_LE(std::abs(shape.elongation), 0.2);
}

// The radii family: each of a shape's three radii within 20% of 1.25, 1
// and 0.8, so that their order swaps; the bump and the knob of each shape's
// own height. Its vertices lie where its parameters say, as above.
TEST(EllipsoidPopulation, TheRadiiFamilySwapsTheOrderOfItsRadii) {
  bool swapped = false;
  for (std::uint64_t seed = 1; seed <= 8; ++seed) {
    const EllipsoidVariant shape = generate_ellipsoid_variant(seed, 600, EllipsoidFamily::radii);
    EXPECT_GE(shape.axes.x, 1.0) << seed;
    EXPECT_LE(shape.axes.x, 1.5) << seed;
    EXPECT_GE(shape.knob_height, 0.0) << seed;
    EXPECT_LE(shape.knob_height, 0.3) << seed;
    swapped = swapped || shape.axes.y < shape.axes.z || shape.axes.x < shape.axes.y;
    double worst = 0;
    for (const Vec3& world : shape.mesh.positions()) {
      const Vec3 unposed = shape.pose.unposed(world);
      const Vec3 u = parameter_of(shape, unposed);
      const double r = 1 + shape.bump_height * bump_term(kEllipsoidBump, u) + shape.knob_height * bump_term(kEllipsoidKnob, u);
      worst = std::max(worst, norm(r * Vec3{shape.axes.x * u.x, shape.axes.y * u.y, shape.axes.z * u.z} + (-1.0) * unposed));
    }
    EXPECT_LT(worst, 1e-12) << seed;
  }
  EXPECT_TRUE(swapped) << "no shape of 8 has its radii in another order";
}

// The bent family: each vertex, unposed and unbent off its arc as
// population.json says, lies on the straight body at its parameter; the
// shape's knobs stay in their ranges.
TEST(GeneratedPopulation, BentBodiesLieWhereTheirParametersSay) {
  for (std::uint64_t seed = 1; seed <= 4; ++seed) {
    const BentBody shape = generate_bent_body(seed, 800);
    const double degrees = shape.bend_angle * 180 / std::numbers::pi;
    EXPECT_GE(degrees, 30.0) << seed;
    EXPECT_LE(degrees, 90.0) << seed;
    EXPECT_NEAR(shape.bend_radius * shape.bend_angle, 2 * shape.axes.z, 1e-12) << seed;
    EXPECT_GT(shape.axes.z, 2.4 * std::max(shape.axes.x, shape.axes.y)) << seed;
    EXPECT_GE(shape.waist_depth, 0.1) << seed;
    EXPECT_LE(shape.waist_depth, 0.35) << seed;
    for (double height : shape.bump_heights) {
      EXPECT_GE(height, 0.05) << seed;
      EXPECT_LE(height, 0.2) << seed;
    }
    const double R = shape.bend_radius;
    double worst = 0;
    for (const Vec3& world : shape.mesh.positions()) {
      const Vec3 x = shape.pose.unposed(world);
      const Vec3 s{R - std::hypot(x.x - R, x.z), x.y, R * std::atan2(x.z, R - x.x)};
      const Vec3 u = normalized({s.x / shape.axes.x, s.y / shape.axes.y, s.z / shape.axes.z});
      double r = 1 - shape.waist_depth * std::exp(-std::pow(u.z / kBentBodyWaistWidth, 2));
      for (std::size_t k = 0; k < 3; ++k) r += shape.bump_heights[k] * bump_term({kBentBodyBumps[k].direction, kBentBodyBumps[k].width, 0}, u);
      worst = std::max(worst, norm(r * Vec3{shape.axes.x * u.x, shape.axes.y * u.y, shape.axes.z * u.z} + (-1.0) * s));
    }
    EXPECT_LT(worst, 1e-9) << seed;
  }
}

TEST(EllipsoidPopulation, ShapesAreMeshedEachOnItsOwnAndPosedAtRandom) {
  std::set<std::size_t> sizes;
  std::vector<Vec3> first_vertex_parameters;
  for (std::uint64_t seed = 1; seed <= 6; ++seed) {
    const EllipsoidVariant shape = generate_ellipsoid_variant(seed, 1500);
    sizes.insert(shape.mesh.vertex_count());
    const Vec3 unposed = shape.pose.unposed(shape.mesh.positions()[0]);
    first_vertex_parameters.push_back(parameter_of(shape, unposed));
  }
  EXPECT_GE(sizes.size(), 2u) << "every shape has the same vertex count";
  // Vertex 0 is somewhere else on every shape: ids say nothing.
  for (std::size_t k = 1; k < first_vertex_parameters.size(); ++k) {
    EXPECT_LT(dot(first_vertex_parameters[k], first_vertex_parameters[0]), 0.999) << "shape " << k;
  }
  // The same seed gives the same shape, bit for bit.
  const EllipsoidVariant again = generate_ellipsoid_variant(3, 1500), once = generate_ellipsoid_variant(3, 1500);
  EXPECT_EQ(again.mesh.positions().front().x, once.mesh.positions().front().x);
  EXPECT_EQ(again.mesh.triangles(), once.mesh.triangles());
}

// The template: the committed-style sphere; the shape: another meshing of
// the sphere stretched along x and squeezed along z. The true place of
// template vertex p on the shape is the stretch of p. Deformed, the template
// must land nearer those places than the nearest shape vertices do.
TEST(TemplateDeformation, FollowsAStretchedShapeBetterThanNearestPoints) {
  const SurfaceMesh template_mesh = generate_mesh_at("sphere", 700);
  const SurfaceMesh shape_mesh = generate_mesh_at("sphere", 1000);
  const Eigen::RowVector3d stretch(1.5, 1.0, 0.6);
  const PointSet template_points = vertex_points(template_mesh);
  PointSet shape_points = vertex_points(shape_mesh);
  shape_points.array().rowwise() *= stretch.array();
  PointSet truth = template_points;
  truth.array().rowwise() *= stretch.array();

  const PointSet deformed = deform_template(template_mesh, template_points, shape_points);
  const MatrixRowTree<PointSet> shape_tree(shape_points);
  double nearest_error = 0, deformed_error = 0;
  for (Eigen::Index v = 0; v < template_points.rows(); ++v) {
    nearest_error += (shape_points.row(shape_tree.nearest(template_points.row(v)).front()) - truth.row(v)).norm();
    deformed_error += (deformed.row(v) - truth.row(v)).norm();
  }
  nearest_error /= double(template_points.rows());
  deformed_error /= double(template_points.rows());
  EXPECT_LT(deformed_error, 0.5 * nearest_error) << "deformed " << deformed_error << ", nearest " << nearest_error;
}

TEST(TemplateDeformation, LeavesATemplateOnItselfWhereItIs) {
  const SurfaceMesh mesh = generate_mesh("torus");
  const PointSet points = vertex_points(mesh);
  EXPECT_EQ((deform_template(mesh, points, points) - points).cwiseAbs().maxCoeff(), 0.0);
}

// The medoid is the shape nearest the others, whatever their order: of
// three spheres scaled 0.9, 1 and 1.2, the middle one; and a shape's
// distance to the population leaves itself out.
// The robust quadric finds a radii shape's own axes and radii through its
// bump and knob (the moments' axes a bump tilts by degrees); a torus has no body.
TEST(EllipsoidBody, FindsTheAxesAndRadiiUnderTheFeatures) {
  for (std::uint64_t seed = 1; seed <= 4; ++seed) {
    const EllipsoidVariant shape = generate_ellipsoid_variant(seed, 900, EllipsoidFamily::radii);
    const std::optional<EllipsoidBody> body = ellipsoid_body(vertex_points(shape.mesh));
    ASSERT_TRUE(body) << seed;
    const std::array<double, 3> radii{shape.axes.x, shape.axes.y, shape.axes.z};
    const auto entry = [&](int row, int column) {
      const Vec3& r = shape.pose.rotation[std::size_t(row)];
      return column == 0 ? r.x : column == 1 ? r.y : r.z;
    };
    for (int k = 0; k < 3; ++k) {
      // The true axis this one lies along (a column of the pose's rotation), and its radius.
      double best = 0;
      int along = 0;
      for (int j = 0; j < 3; ++j) {
        const Eigen::Vector3d axis(entry(0, j), entry(1, j), entry(2, j));
        const double cosine = std::abs(body->axes.row(k).dot(axis));
        if (cosine > best) {
          best = cosine;
          along = j;
        }
      }
      EXPECT_GT(best, std::cos(std::numbers::pi / 180)) << seed << " axis " << k;
      EXPECT_NEAR(body->radii(k) / shape.pose.scale, radii[std::size_t(along)], 0.02) << seed << " axis " << k;
    }
  }
  EXPECT_FALSE(ellipsoid_body(vertex_points(generate_mesh("torus"))));
}

TEST(PopulationAlignment, TheMedoidIsTheShapeNearestTheOthers) {
  const PointSet sphere = alignment_points(generate_mesh("sphere"));
  const std::vector<PointSet> shapes{1.2 * sphere, 0.9 * sphere, 1.0 * sphere};
  const AlignedShapes population(shapes);
  EXPECT_EQ(population.medoid(), 2u);
  EXPECT_EQ(AlignedShapes({shapes[2], shapes[0], shapes[1]}).medoid(), 0u);
  EXPECT_EQ(AlignedShapes({shapes[2]}).distance_to_population(shapes[2], 0), 0.0);
  EXPECT_LT(population.distance_to_population(shapes[2], 2), population.distance_to_population(shapes[0], 0));
}

// A sphere's points with two bumps (up and along x), and the same shape
// turned half round about y: a pose a fit might take for it.
PointSet bumped_sphere(double height) {
  PointSet points = alignment_points(generate_mesh("sphere"));
  const Eigen::RowVector3d up(0, 0, 1), along(1, 0, 0);
  for (Eigen::Index i = 0; i < points.rows(); ++i) {
    const Eigen::RowVector3d u = points.row(i).normalized();
    points.row(i) *= 1 + height * (std::exp(-(1 - u.dot(up)) / 0.05) + 0.5 * std::exp(-(1 - u.dot(along)) / 0.05));
  }
  return points;
}

PointSet half_turned(const PointSet& points) {
  return points * Eigen::Vector3d(-1, 1, -1).asDiagonal();  // about y
}

TEST(PopulationAlignment, ThePopulationChoosesAmongThePosesAFitLeavesOpen) {
  const PointSet right = bumped_sphere(0.2), other_right = bumped_sphere(0.15);
  // Shape 1's own fit chose the turned pose, shape 2's the right one.
  const PoseCandidates candidates({{right}, {half_turned(other_right), other_right}, {other_right, half_turned(other_right)}, {right}});
  std::vector<std::vector<double>> distances;
  for (std::size_t k = 0; k < candidates.shapes(); ++k) distances.push_back(candidates.distances(k));
  EXPECT_TRUE(distances[0].empty());
  EXPECT_EQ(distances[1].size(), 2u * (1 + 2 + 1));  // each candidate to every reference's candidates
  const std::vector<PoseChoice> choices = candidates.choose(distances);
  EXPECT_EQ(choices[0].chosen, 0u);
  EXPECT_EQ(choices[0].ratio, 0.0);  // one candidate: nothing to choose
  EXPECT_EQ(choices[1].chosen, 1u);
  EXPECT_EQ(choices[2].chosen, 0u);
  EXPECT_LT(choices[1].ratio, 0.9);
  EXPECT_LT(choices[2].ratio, 0.9);
  // Two shapes: the other is the template, whose fit already chose.
  const PoseCandidates pair({{right}, {half_turned(other_right), other_right}});
  EXPECT_EQ(pair.choose({pair.distances(0), pair.distances(1)})[1].chosen, 0u);
}

// Four ellipsoid shapes on disk, and the spread of particle i across them
// measured in their common parameter, as scripts/correspondence_error.py does.
class SmallPopulation : public ::testing::Test {
 protected:
  static constexpr std::size_t kParticles = 96;

  void SetUp() override {
    directory_ = std::filesystem::temp_directory_path() / ("mp_population_" + std::to_string(::getpid()));
    std::filesystem::create_directories(directory_);
    for (std::uint64_t seed = 1; seed <= 4; ++seed) {
      shapes_.push_back(generate_ellipsoid_variant(seed, 900));
      files_.push_back(directory_ / ("shape_" + std::to_string(seed) + ".off"));
      write_mesh(shapes_.back().mesh, files_.back());
    }
  }
  void TearDown() override { std::filesystem::remove_all(directory_); }

  // `even_enough` 1: the refinement's places, none held back.
  PopulationCorrespondence correspond(std::size_t iterations, double weight, bool pack,
                                      double even_enough = JointRefinementOptions{}.even_enough) const {
    return correspond(files_, iterations, weight, pack, even_enough);
  }
  static PopulationCorrespondence correspond(const std::vector<std::filesystem::path>& files, std::size_t iterations,
                                             double weight, bool pack,
                                             double even_enough = JointRefinementOptions{}.even_enough) {
    PopulationRequest request;
    request.meshes = files;
    request.run.particles = kParticles;
    request.quiet = true;
    request.refinement.iterations = iterations;
    request.refinement.correspondence_weight = weight;
    request.refinement.pack = pack;
    request.refinement.even_enough = even_enough;
    return correspond_population(request);
  }

  // Shape s's closest pair of particles (straight), in its hexagonal spacings.
  double closest_pair(const PopulationCorrespondence& population, std::size_t s) const {
    const PointSet& p = population.shapes[s].particles;
    double closest = std::numeric_limits<double>::infinity();
    for (Eigen::Index i = 0; i < p.rows(); ++i) {
      for (Eigen::Index j = i + 1; j < p.rows(); ++j) closest = std::min(closest, (p.row(i) - p.row(j)).norm());
    }
    return closest / hexagonal_spacing(shapes_[s].mesh.area(), kParticles);
  }

  // Shape s's nn_cv when its own run (the default) spreads the particles.
  DistributionQuality own_quality(std::size_t s) const {
    RunRequest run;
    run.particles = kParticles;
    run.quiet = true;
    return run_pipeline(shapes_[s].mesh, run).quality;
  }

  // Mean over particles of the mean angle from their mean direction, in
  // particle spacings of the unit sphere.
  double spread(const PopulationCorrespondence& population) const {
    const Eigen::Index count = population.shapes.front().particles.rows();
    double total = 0;
    for (Eigen::Index i = 0; i < count; ++i) {
      std::vector<Vec3> directions;
      Vec3 sum{};
      for (std::size_t s = 0; s < shapes_.size(); ++s) {
        const EllipsoidVariant& shape = shapes_[s];
        const auto& p = population.shapes[s].particles;
        const Vec3 world{p(i, 0), p(i, 1), p(i, 2)};
        directions.push_back(
            parameter_of(shape, shape.pose.unposed(world)));
        sum = sum + directions.back();
      }
      for (const Vec3& u : directions) total += std::acos(std::clamp(dot(u, normalized(sum)), -1.0, 1.0));
    }
    const double spacing = std::sqrt(8 * std::numbers::pi / (std::sqrt(3.0) * double(count)));
    return total / double(count * Eigen::Index(shapes_.size())) / spacing;
  }

  static double worst_nn_cv(const PopulationCorrespondence& population) {
    double worst = 0;
    for (const ShapeCorrespondence& shape : population.shapes) worst = std::max(worst, shape.quality.nn_cv.value());
    return worst;
  }

  std::filesystem::path directory_;
  std::vector<EllipsoidVariant> shapes_;
  std::vector<std::filesystem::path> files_;
};

// The joint refinement evens every shape out, and its correspondence step is
// what keeps particle i in place while it does: without it (weight 0) the
// same iterations let the particles drift apart across shapes.
TEST_F(SmallPopulation, JointRefinementEvensShapesOutWhileTheCorrespondenceHolds) {
  const PopulationCorrespondence transferred = correspond(0, 0.1, false, 1.0);
  const PopulationCorrespondence refined = correspond(600, 0.1, false, 1.0);
  const PopulationCorrespondence unheld = correspond(600, 0.0, false, 1.0);
  EXPECT_EQ(refined.refinement.overlap.size(), 600u);
  EXPECT_LT(worst_nn_cv(refined), 0.8 * worst_nn_cv(transferred))
      << "refined " << worst_nn_cv(refined) << ", transferred " << worst_nn_cv(transferred);
  EXPECT_LT(spread(refined), 0.3);
  EXPECT_LT(spread(refined), 0.85 * spread(unheld)) << "held " << spread(refined) << ", unheld " << spread(unheld);
  // Row i is one particle: the template's stays near where its run put it.
  EXPECT_LT(spread(transferred), 0.3);
}

// The packing ends every shape about as evenly spread as its own run
// spreads it, by the measures of a packing (rho at least 0.7, and no hole
// over 1.15 times its own run's cover), and the correspondence still holds.
// Not nn_cv against the own run's: both are near 0.003 here, so a ratio of
// them is noise.
TEST_F(SmallPopulation, PackingEvensEachShapeAsItsOwnRunDoes) {
  const PopulationCorrespondence packed = correspond(200, 0.1, true);
  EXPECT_GT(packed.refinement.packing_rounds, 0u);
  for (std::size_t s = 0; s < shapes_.size(); ++s) {
    const DistributionQuality own = own_quality(s), shape = packed.shapes[s].quality;
    EXPECT_GE(shape.rho.value(), 0.7) << "shape " << s;
    EXPECT_LE(shape.cover.value(), 1.15 * own.cover.value())
        << "shape " << s << ": cover " << shape.cover.value() << " against its own run's " << own.cover.value();
  }
  EXPECT_LT(spread(packed), 0.3);
}

// Each shape keeps only as much of its evening as keeps its closest pair
// `even_enough` spacings apart: particle i then lies nearer its places on
// the other shapes than where the refinement left it.
TEST_F(SmallPopulation, EachShapeKeepsOnlyTheEveningItNeeds) {
  const PopulationCorrespondence evened = correspond(200, 0.1, true, 1.0);
  const PopulationCorrespondence held = correspond(200, 0.1, true, 0.75);
  EXPECT_EQ(evened.refinement.evening_kept, std::vector<double>(shapes_.size(), 1.0));
  ASSERT_EQ(held.refinement.evening_kept.size(), shapes_.size());
  std::size_t held_back = 0;
  for (std::size_t s = 0; s < shapes_.size(); ++s) {
    const double kept = held.refinement.evening_kept[s];
    EXPECT_GE(kept, 0.0);
    EXPECT_LE(kept, 1.0);
    if (kept == 1.0) continue;
    ++held_back;
    EXPECT_GE(closest_pair(held, s), 0.75) << "shape " << s << " kept " << kept;
    EXPECT_GE(held.shapes[s].quality.rho.value(), 0.75) << "shape " << s;
  }
  EXPECT_GT(held_back, 0u);
  EXPECT_LT(spread(held), spread(evened)) << "held " << spread(held) << ", evened " << spread(evened);
}

// At about three vertices a particle the correspondence step held holes
// open on a knob or a flank, between the vertices, where a cover measured
// at the vertices did not see them: on these shapes (`generate
// --population 4 --family radii --seed 6 --vertices 1700`) shape 1 ended
// at 1.17 to 1.23 times its own run's cover at n = 512. The packing's hole
// pull closes them.
TEST(RadiiPopulation, PackingLeavesNoHoleBetweenTheVertices) {
  constexpr std::size_t kParticles = 512;
  const std::filesystem::path directory =
      std::filesystem::temp_directory_path() / ("mp_radii_" + std::to_string(::getpid()));
  std::filesystem::create_directories(directory);
  SplitMix64 seeds(6);
  std::vector<SurfaceMesh> meshes;
  PopulationRequest request;
  for (std::size_t s = 0; s < 4; ++s) {
    meshes.push_back(generate_ellipsoid_variant(seeds.next(), 1700, EllipsoidFamily::radii).mesh);
    request.meshes.push_back(directory / ("radii_" + std::to_string(s) + ".off"));
    write_mesh(meshes.back(), request.meshes.back());
  }
  request.run.particles = kParticles;
  request.quiet = true;
  const PopulationCorrespondence packed = correspond_population(request);
  std::filesystem::remove_all(directory);
  for (std::size_t s = 0; s < meshes.size(); ++s) {
    RunRequest run;
    run.particles = kParticles;
    run.quiet = true;
    const double own = run_pipeline(meshes[s], run).quality.cover.value();
    EXPECT_LE(packed.shapes[s].quality.cover.value(), 1.15 * own)
        << "shape " << s << ": cover " << packed.shapes[s].quality.cover.value() << " against its own run's " << own;
  }
}

// Where the packing leaves the shapes less spread than the iterations did,
// it is undone: on sheets thinner than a spacing its particles on the two
// sides, which do not face each other, come together (as on a body's hands),
// so the iterations' places stay. On the ellipsoids it spreads, and stays.
TEST_F(SmallPopulation, PackingIsUndoneWhereItLeavesTheShapesLessSpread) {
  const PopulationCorrespondence iterated = correspond(200, 0.1, false, 1.0);
  const PopulationCorrespondence packed = correspond(200, 0.1, true, 1.0);
  EXPECT_FALSE(packed.refinement.packing_undone);
  EXPECT_NE(packed.shapes.front().particles, iterated.shapes.front().particles);
  std::vector<std::filesystem::path> sheets;
  for (std::size_t s = 0; s < shapes_.size(); ++s) {
    std::vector<Vec3> flattened = shapes_[s].mesh.positions();
    for (Vec3& p : flattened) p.z *= 0.02;
    sheets.push_back(directory_ / ("sheet_" + std::to_string(s) + ".off"));
    write_mesh(SurfaceMesh(flattened, shapes_[s].mesh.triangles()), sheets.back());
  }
  const PopulationCorrespondence sheet_iterated = correspond(sheets, 200, 0.1, false, 1.0);
  const PopulationCorrespondence sheet_packed = correspond(sheets, 200, 0.1, true, 1.0);
  EXPECT_TRUE(sheet_packed.refinement.packing_undone);
  EXPECT_GT(sheet_packed.refinement.packing_rounds, 0u);
  for (std::size_t s = 0; s < sheets.size(); ++s) {
    EXPECT_EQ(sheet_packed.shapes[s].particles, sheet_iterated.shapes[s].particles) << "shape " << s;
  }
}

// Issue 31: the same population moved, turned and scaled gives the same
// model. Every shape, the template too, is posed anew at random; particle i
// lands where it landed before, carried by the new pose, and the model
// holds the same share of the variance. Not to the bit: the template's own
// run is not (its relaxation holds particles in an order of the bounding
// box, and a packing amplifies rounding), and in this test it alone puts
// particles 0.13 spacings (median) from where they were; after the
// refinement and packing 0.23 (90th percentile 0.39), where a shape placed
// at random is several spacings off (batch: 5 and more).
TEST_F(SmallPopulation, TheSamePopulationMovedGivesTheSameModel) {
  std::mt19937_64 random(31);
  std::normal_distribution<double> normal;
  std::uniform_real_distribution<double> uniform(0, 1);
  struct Pose {
    Eigen::Matrix3d rotation;
    double scale;
    Eigen::RowVector3d offset;
  };
  std::vector<Pose> poses;
  std::vector<std::filesystem::path> moved_files;
  for (std::size_t s = 0; s < shapes_.size(); ++s) {
    const Eigen::Quaterniond turn =
        Eigen::Quaterniond(normal(random), normal(random), normal(random), normal(random)).normalized();
    poses.push_back({turn.toRotationMatrix(), 0.5 + 1.5 * uniform(random),
                     Eigen::RowVector3d(10 * uniform(random) - 5, 10 * uniform(random) - 5, 10 * uniform(random) - 5)});
    std::vector<Vec3> positions;
    for (const Vec3& p : shapes_[s].mesh.positions()) {
      const Eigen::RowVector3d moved = poses.back().scale * Eigen::RowVector3d(p.x, p.y, p.z) *
                                           poses.back().rotation.transpose() + poses.back().offset;
      positions.push_back({moved(0), moved(1), moved(2)});
    }
    moved_files.push_back(directory_ / ("moved_" + std::to_string(s) + ".off"));
    write_mesh(SurfaceMesh(positions, shapes_[s].mesh.triangles()), moved_files.back());
  }
  const PopulationCorrespondence original = correspond(200, 0.1, true);
  const PopulationCorrespondence moved = correspond(moved_files, 200, 0.1, true);

  std::vector<double> offsets;  // per particle and shape, in the shape's hexagonal spacings
  std::vector<PointSet> original_sets, moved_sets;
  for (std::size_t s = 0; s < shapes_.size(); ++s) {
    const Pose& pose = poses[s];
    const PointSet back =
        ((moved.shapes[s].particles.rowwise() - pose.offset) * pose.rotation) / pose.scale;  // the pose undone
    const double spacing = hexagonal_spacing(shapes_[s].mesh.area(), kParticles);
    for (Eigen::Index i = 0; i < back.rows(); ++i) {
      offsets.push_back((back.row(i) - original.shapes[s].particles.row(i)).norm() / spacing);
    }
    original_sets.push_back(original.shapes[s].particles);
    moved_sets.push_back(moved.shapes[s].particles);
  }
  std::sort(offsets.begin(), offsets.end());
  const double median = offsets[offsets.size() / 2], p90 = offsets[offsets.size() * 9 / 10];
  EXPECT_LT(median, 0.35) << "90th percentile " << p90;
  EXPECT_LT(p90, 0.6);
  const ShapeModel a = build_shape_model(original_sets, true, 10, 1, true);
  const ShapeModel b = build_shape_model(moved_sets, true, 10, 1, true);
  EXPECT_NEAR(a.quality.compactness[0], b.quality.compactness[0], 0.05);  // 0.94 and 0.97 here
  EXPECT_NEAR(a.quality.compactness[1], b.quality.compactness[1], 0.05);
}

// The one k-d tree over a PointSet's rows: the nearest rows, nearest first,
// as a search of every row finds them.
TEST(MatrixRowTree, FindsTheNearestRowsInOrder) {
  std::mt19937_64 random(49);
  std::uniform_real_distribution<double> uniform(-1, 1);
  PointSet points(400, 3);
  for (Eigen::Index i = 0; i < points.rows(); ++i) points.row(i) << uniform(random), uniform(random), uniform(random);
  const MatrixRowTree<PointSet> tree(points);
  for (int q = 0; q < 20; ++q) {
    const Eigen::RowVector3d query(uniform(random), uniform(random), uniform(random));
    std::vector<std::uint32_t> all(std::size_t(points.rows()));
    for (std::uint32_t i = 0; i < all.size(); ++i) all[i] = i;
    std::sort(all.begin(), all.end(), [&](std::uint32_t a, std::uint32_t b) {
      return (points.row(a) - query).squaredNorm() < (points.row(b) - query).squaredNorm();
    });
    all.resize(8);
    EXPECT_EQ(tree.nearest(query, 8), all);
  }
  EXPECT_EQ(tree.nearest(points.row(7)).front(), 7u);
  EXPECT_EQ(tree.nearest(points.row(0), 1000).size(), 400u);  // no more than there are
}

}  // namespace
}  // namespace meshparticles::testing
