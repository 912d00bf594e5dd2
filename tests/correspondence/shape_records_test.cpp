// correspondence/shape_records: a shape's result and the refinement's
// record read back from their JSON text exactly, to the bit (what a resume
// and the ranks rely on); values no run could have written are refused.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include "common/json_text.hpp"
#include "correspondence/shape_records.hpp"

namespace meshparticles::testing {
namespace {

// Through the text a checkpoint holds, as it reads it back.
nlohmann::json through_text(const nlohmann::json& json) { return nlohmann::json::parse(json_text(json)); }

// Numbers whose shortest text is long, or that are near the edges of a double.
const double kAwkward[] = {0.1 + 0.2, 1.0 / 3.0, -2.0 / 7.0, 1e-300, 5e-324, 1.7976931348623157e308, -0.0, 123456789.125};

ShapeCorrespondence awkward_shape() {
  ShapeCorrespondence shape;
  shape.mesh = "/data/shape one.off";
  shape.vertices = 20;
  shape.alignment.to_common.scale = kAwkward[1];
  shape.alignment.to_common.rotation = Eigen::AngleAxisd(kAwkward[0], Eigen::Vector3d(1, 2, 3).normalized()).toRotationMatrix();
  shape.alignment.to_common.translation = Eigen::Vector3d(kAwkward[2], kAwkward[3], kAwkward[7]);
  shape.alignment.rms = kAwkward[4];
  shape.alignment.iterations = 17;
  shape.alignment.from_principal_axes = true;
  shape.alignment.runner_up = {1.0 + kAwkward[0], 179.5, kAwkward[1]};
  shape.alignment.relief = {true, 0.7 + 1e-16, kAwkward[2], 179.25, true};
  shape.topology = {1, 2, -2, 1};
  shape.particles.resize(3, 3);
  for (Eigen::Index i = 0; i < 3; ++i) {
    for (Eigen::Index c = 0; c < 3; ++c) shape.particles(i, c) = kAwkward[std::size_t(i * 3 + c) % 8];
    shape.locations.push_back({{std::uint32_t(i), std::uint32_t(i + 1), 19}, {kAwkward[1], kAwkward[0], 1 - kAwkward[1] - kAwkward[0]}});
  }
  shape.quality.particles = 3;
  shape.quality.nn_min = kAwkward[0];
  shape.quality.nn_mean = kAwkward[1];
  shape.quality.nn_std = kAwkward[3];
  shape.quality.nn_cv = kAwkward[2] * -1;
  shape.quality.d_hex = kAwkward[7];
  shape.quality.rho = 0.75;
  shape.quality.cover = kAwkward[1] * 4;
  shape.quality.energy = kAwkward[5];
  return shape;
}

template <typename T>
bool same_bits(const T& a, const T& b) {
  return std::memcmp(&a, &b, sizeof(T)) == 0;
}

TEST(ShapeRecords, AShapeReadsBackToTheBit) {
  const ShapeCorrespondence shape = awkward_shape();
  const nlohmann::json json = through_text(shape_json(shape));
  EXPECT_NO_THROW(check_shape_json(json, shape.mesh.string(), 20, 3));
  const ShapeCorrespondence back = shape_from_json(json);
  EXPECT_EQ(back.mesh, shape.mesh);
  EXPECT_EQ(back.vertices, shape.vertices);
  EXPECT_EQ(back.particles, shape.particles);
  EXPECT_TRUE(same_bits(back.particles(2, 0), shape.particles(2, 0)));  // -0.0 stays -0.0
  EXPECT_TRUE(std::signbit(back.particles(2, 0)));
  ASSERT_EQ(back.locations.size(), 3u);
  for (std::size_t i = 0; i < 3; ++i) {
    EXPECT_EQ(back.locations[i].corners, shape.locations[i].corners);
    EXPECT_EQ(back.locations[i].weights, shape.locations[i].weights);
  }
  const MeshAlignment& a = back.alignment;
  EXPECT_EQ(a.to_common.scale, shape.alignment.to_common.scale);
  EXPECT_EQ(a.to_common.rotation, shape.alignment.to_common.rotation);
  EXPECT_EQ(a.to_common.translation, shape.alignment.to_common.translation);
  EXPECT_EQ(a.rms, shape.alignment.rms);
  EXPECT_EQ(a.iterations, 17u);
  EXPECT_TRUE(a.from_principal_axes);
  EXPECT_EQ(a.runner_up.rms_ratio, shape.alignment.runner_up.rms_ratio);
  EXPECT_EQ(a.runner_up.degrees, 179.5);
  EXPECT_EQ(a.runner_up.rms, shape.alignment.runner_up.rms);
  EXPECT_TRUE(a.relief.measured);
  EXPECT_EQ(a.relief.agreement, shape.alignment.relief.agreement);
  EXPECT_EQ(a.relief.runner_up, shape.alignment.relief.runner_up);
  EXPECT_EQ(a.relief.runner_up_degrees, 179.25);
  EXPECT_TRUE(a.relief.canonical);
  EXPECT_EQ(back.topology, shape.topology);
  EXPECT_EQ(back.quality.nn_min, shape.quality.nn_min);
  EXPECT_EQ(back.quality.nn_cv, shape.quality.nn_cv);
  EXPECT_EQ(back.quality.cover, shape.quality.cover);
  EXPECT_EQ(back.quality.energy, shape.quality.energy);
  // Written again, the same text.
  EXPECT_EQ(json_text(shape_json(back)), json_text(shape_json(shape)));
}

// No runner-up (infinite ratio, which JSON cannot hold), no relief choice,
// a relief choice with no other end state (-infinity), no genus: each comes
// back as it was.
TEST(ShapeRecords, WhatJsonCannotHoldComesBackAsItWas) {
  MeshAlignment alignment;
  const MeshAlignment back = alignment_from_json(through_text(alignment_json(alignment)));
  EXPECT_TRUE(std::isinf(back.runner_up.rms_ratio));
  EXPECT_TRUE(std::isinf(back.runner_up.rms));
  EXPECT_FALSE(back.relief.measured);
  EXPECT_TRUE(relief_json(alignment.relief).is_null());
  alignment.relief = {true, 0.5};
  const MeshAlignment alone = alignment_from_json(through_text(alignment_json(alignment)));
  EXPECT_TRUE(alone.relief.measured);
  EXPECT_EQ(alone.relief.agreement, 0.5);
  EXPECT_TRUE(std::isinf(alone.relief.runner_up) && alone.relief.runner_up < 0);
  MeshTopology nonmanifold{1, 0, 3, std::nullopt};
  EXPECT_EQ(topology_from_json(through_text(topology_json(nonmanifold))), nonmanifold);
}

TEST(ShapeRecords, LocationsAndTheRecordReadBackToTheBit) {
  // Weights that are barycentric (a decode refuses others) but awkward to
  // write: each pair's third is what makes the sum 1.
  const double pairs[4][2] = {{0.1 + 0.2, 1.0 / 3.0}, {1e-300, 5e-324}, {2.0 / 7.0, 0.5}, {-0.0, 1.0 / 3.0}};
  std::vector<SurfaceLocation> locations;
  for (std::uint32_t t = 0; t < 4; ++t) {
    const double a = pairs[t][0], b = pairs[t][1];
    locations.push_back({t, {a, b, 1 - a - b}, {kAwkward[t + 3], kAwkward[7], -kAwkward[0]}});
  }
  const std::vector<SurfaceLocation> back = locations_from_json(through_text(locations_json(locations)), 4, 4);
  ASSERT_EQ(back.size(), 4u);
  for (std::size_t i = 0; i < 4; ++i) {
    EXPECT_EQ(back[i].triangle, locations[i].triangle);
    EXPECT_EQ(back[i].weights, locations[i].weights);
    EXPECT_EQ(back[i].at.x, locations[i].at.x);
    EXPECT_EQ(back[i].at.y, locations[i].at.y);
    EXPECT_EQ(back[i].at.z, locations[i].at.z);
  }

  JointRefinementRecord record;
  record.overlap = {kAwkward[0], kAwkward[1]};
  record.correspondence_step = {kAwkward[2], kAwkward[3]};
  record.packing_spacing = {kAwkward[4]};
  record.packing_correspondence_step = {kAwkward[7]};
  record.packing_rounds = 1;
  record.packing_released = 2;
  record.packing_undone = true;
  record.evening_kept = {0.3, 1.0};
  const JointRefinementRecord again = refinement_from_json(through_text(refinement_json(record)));
  EXPECT_EQ(again.overlap, record.overlap);
  EXPECT_EQ(again.correspondence_step, record.correspondence_step);
  EXPECT_EQ(again.packing_spacing, record.packing_spacing);
  EXPECT_EQ(again.packing_correspondence_step, record.packing_correspondence_step);
  EXPECT_EQ(again.packing_rounds, 1u);
  EXPECT_EQ(again.packing_released, 2u);
  EXPECT_TRUE(again.packing_undone);
  EXPECT_EQ(again.evening_kept, record.evening_kept);
}

// What a checkpoint gives back is checked against the mesh it is for.
TEST(ShapeRecords, ValuesNoRunCouldHaveWrittenAreRefused) {
  std::vector<SurfaceLocation> locations(2, SurfaceLocation{3, {0.5, 0.25, 0.25}, {1, 2, 3}});
  const nlohmann::json rows = locations_json(locations);
  EXPECT_NO_THROW(locations_from_json(rows, 4, 2));
  EXPECT_THROW(locations_from_json(rows, 3, 2), std::invalid_argument);  // triangle 3 of 3
  EXPECT_THROW(locations_from_json(rows, 4, 3), std::invalid_argument);  // a row short
  nlohmann::json negative = rows;
  negative[0][0] = -1;
  EXPECT_THROW(locations_from_json(negative, 4, 2), std::invalid_argument);
  nlohmann::json not_a_number = rows;
  not_a_number[1][2] = nullptr;
  EXPECT_ANY_THROW(locations_from_json(not_a_number, 4, 2));

  const nlohmann::json shape = shape_json(awkward_shape());
  const std::string mesh = awkward_shape().mesh.string();
  EXPECT_THROW(check_shape_json(shape, mesh, 19, 3), std::invalid_argument);  // another mesh's size
  EXPECT_THROW(check_shape_json(shape, "/data/shape two.off", 20, 3), std::invalid_argument);  // another's entry
  EXPECT_THROW(check_shape_json(shape, mesh, 20, 2), std::invalid_argument);  // other particles
  nlohmann::json past_end = shape;
  past_end["vertices"] = 19;
  EXPECT_THROW(check_shape_json(past_end, mesh, 19, 3), std::invalid_argument);  // corner 19 of 19
  nlohmann::json missing = shape;
  missing.erase("topology");
  EXPECT_THROW(check_shape_json(missing, mesh, 20, 3), nlohmann::json::exception);
  nlohmann::json told_by_nothing = shape;
  told_by_nothing["alignment"]["relief"]["by"] = "a guess";
  EXPECT_THROW(shape_from_json(told_by_nothing), std::invalid_argument);
}

}  // namespace
}  // namespace meshparticles::testing
