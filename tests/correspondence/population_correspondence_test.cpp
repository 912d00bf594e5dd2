// correspondence/population_correspondence, the feature layer: whole
// populations of fixtures/ (their known map) through correspond_population,
// the transfer, the joint refinement, the packing and the hold-back together.
// The modules' own contracts are tested in the files named after them.
#include <gtest/gtest.h>

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <limits>
#include <numbers>
#include <random>
#include <string>
#include <vector>

#include "common/random.hpp"
#include "common/user_error.hpp"
#include "correspondence/joint_refinement.hpp"
#include "correspondence/mesh_alignment.hpp"
#include "correspondence/population_correspondence.hpp"
#include "fixtures/mesh_generator.hpp"
#include "mesh/mesh_writer.hpp"
#include "particles/particle_params.hpp"
#include "pipeline/mesh_input.hpp"
#include "pipeline/run_pipeline.hpp"
#include "shape_model/shape_model.hpp"

namespace meshparticles::testing {
namespace {

// The parameter of an unposed surface point, as population.json says.
Vec3 parameter_of(const EllipsoidVariant& shape, Vec3 unposed) {
  return normalized({unposed.x / shape.axes.x, unposed.y / shape.axes.y, unposed.z / shape.axes.z});
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
// The template is sampled on spread's working mesh at the template's own
// resolution (kTemplateVerticesPerParticle, kTemplateLongestEdge), not at
// the default run's: its particles are those of a run asked for that mesh,
// measured alike, and not the default run's.
TEST_F(SmallPopulation, TheTemplateIsSampledAtItsOwnResolution) {
  const PopulationCorrespondence population = correspond(0, 0.1, false);
  RunRequest run;
  run.particles = kParticles;
  run.quiet = true;
  run.vertices_per_particle = kTemplateVerticesPerParticle;
  run.longest_edge = kTemplateLongestEdge;
  const DistributionQuality template_run = run_pipeline(load_mesh(files_.front(), true), run).quality;
  EXPECT_EQ(population.template_quality.rho, template_run.rho);
  EXPECT_EQ(population.template_quality.nn_cv, template_run.nn_cv);
  EXPECT_EQ(population.template_quality.energy, template_run.energy);
  run.vertices_per_particle.reset();
  run.longest_edge.reset();
  EXPECT_NE(population.template_quality.nn_cv, run_pipeline(load_mesh(files_.front(), true), run).quality.nn_cv);
}

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
  constexpr std::size_t kRadiiParticles = 512;
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
  request.run.particles = kRadiiParticles;
  request.quiet = true;
  const PopulationCorrespondence packed = correspond_population(request);
  std::filesystem::remove_all(directory);
  for (std::size_t s = 0; s < meshes.size(); ++s) {
    RunRequest run;
    run.particles = kRadiiParticles;
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


// What cannot be read, and more particles than the template has, are
// refused naming the mesh, before any work.
TEST(PopulationCorrespondence, RefusesAMissingMeshAndTooManyParticles) {
  const std::filesystem::path directory =
      std::filesystem::temp_directory_path() / ("mp_population_refusals_" + std::to_string(::getpid()));
  std::filesystem::create_directories(directory);
  PopulationRequest request;
  request.meshes = {directory / "template.off", directory / "missing.off"};
  write_mesh(generate_mesh("tetrahedron"), request.meshes.front());
  request.run.particles = 2;
  request.quiet = true;
  try {
    correspond_population(request);
    ADD_FAILURE() << "a missing mesh was taken";
  } catch (const UserError& error) {
    EXPECT_NE(std::string(error.what()).find("missing.off"), std::string::npos) << error.what();
  }
  request.meshes.back() = request.meshes.front();
  request.run.particles = 5;
  try {
    correspond_population(request);
    ADD_FAILURE() << "5 particles on 4 vertices were taken";
  } catch (const UserError& error) {
    EXPECT_NE(std::string(error.what()).find("-n 5"), std::string::npos) << error.what();
  }
  std::filesystem::remove_all(directory);
}

// Copies of the template, moved, turned and scaled: the transfer puts
// particle i on each where the pose carries the template's.
TEST(PopulationCorrespondence, ACopyOfTheTemplateTakesItsParticlesWhereThePoseCarriesThem) {
  const std::filesystem::path directory =
      std::filesystem::temp_directory_path() / ("mp_population_copies_" + std::to_string(::getpid()));
  std::filesystem::create_directories(directory);
  const SurfaceMesh mesh = generate_ellipsoid_variant(4, 400).mesh;
  const Eigen::Matrix3d turn = Eigen::AngleAxisd(1.3, Eigen::Vector3d(0.2, 1, -0.4).normalized()).toRotationMatrix();
  const double scale = 2.5;
  const Eigen::Vector3d shift(4, -3, 1);
  std::vector<Vec3> positions;
  for (const Vec3& p : mesh.positions()) {
    const Eigen::Vector3d q = scale * (turn * Eigen::Vector3d(p.x, p.y, p.z)) + shift;
    positions.push_back({q(0), q(1), q(2)});
  }
  PopulationRequest request;
  request.meshes = {directory / "template.off", directory / "copy.off", directory / "same.off"};
  write_mesh(mesh, request.meshes[0]);
  write_mesh(SurfaceMesh(positions, mesh.triangles()), request.meshes[1]);
  write_mesh(mesh, request.meshes[2]);
  request.run.particles = 24;
  request.refinement.iterations = 0;
  request.quiet = true;
  const PopulationCorrespondence population = correspond_population(request);
  std::filesystem::remove_all(directory);
  ASSERT_EQ(population.shapes.size(), 3u);
  const PointSet& template_particles = population.shapes[0].particles;
  ASSERT_EQ(template_particles.rows(), 24);
  const PointSet carried = ((scale * template_particles * turn.transpose()).rowwise() + shift.transpose()).eval();
  EXPECT_LT((population.shapes[1].particles - carried).cwiseAbs().maxCoeff(), 1e-6 * scale);
  EXPECT_LT((population.shapes[2].particles - template_particles).cwiseAbs().maxCoeff(), 1e-6);
}

}  // namespace
}  // namespace meshparticles::testing
