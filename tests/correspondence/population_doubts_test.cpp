// population_doubts: every doubt names its shape, and a shape without one
// gets no line.
#include "correspondence/population_doubts.hpp"

#include <gtest/gtest.h>

namespace meshparticles {
namespace {

ShapeCorrespondence sphere_shape(const std::string& name, std::size_t particles) {
  ShapeCorrespondence shape;
  shape.mesh = name;
  shape.topology.components = 1;
  shape.topology.euler_characteristic = 2;
  shape.topology.genus = 0;
  shape.particles = PointSet::Zero(Eigen::Index(particles), 3);
  return shape;
}

TEST(PopulationDoubts, NoneForAPopulationWithoutDoubts) {
  EXPECT_TRUE(population_doubts({sphere_shape("a.off", 8), sphere_shape("b.off", 8)}).empty());
  EXPECT_TRUE(population_doubts({}).empty());
}

TEST(PopulationDoubts, StackedParticlesNameTheirShape) {
  std::vector<ShapeCorrespondence> shapes = {sphere_shape("a.off", 8), sphere_shape("b.off", 8)};
  shapes[1].quality.stacked = 2;
  const std::vector<std::string> doubts = population_doubts(shapes);
  ASSERT_EQ(doubts.size(), 1u);
  EXPECT_EQ(doubts[0].rfind("b.off: 2 of its 8 particles lie at another's place", 0), 0u) << doubts[0];
}

TEST(PopulationDoubts, AnotherTopologyAndAnOpenPoseNameTheirShapes) {
  std::vector<ShapeCorrespondence> shapes = {sphere_shape("a.off", 8), sphere_shape("torus.off", 8),
                                             sphere_shape("c.off", 8)};
  shapes[1].topology.euler_characteristic = 0;
  shapes[1].topology.genus = 1;
  shapes[2].alignment.population_ratio = 0.99;  // the population barely prefers the pose chosen
  shapes[2].alignment.runner_up.degrees = 180;
  const std::vector<std::string> doubts = population_doubts(shapes);
  ASSERT_EQ(doubts.size(), 2u);
  EXPECT_NE(doubts[0].find("torus.off (1 component, genus 1"), std::string::npos) << doubts[0];
  EXPECT_EQ(doubts[1].rfind("c.off: a pose 180 degrees from the one chosen is only 1.0% farther from", 0), 0u)
      << doubts[1];
}

}  // namespace
}  // namespace meshparticles
