// correspondence/correspondence_outputs: the files correspond promises in
// its --out (shapes/, model/, summary.json), and a folder that holds what
// it did not write refused before any work.
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "common/user_error.hpp"
#include "correspondence/correspondence_outputs.hpp"
#include "shape_model/shape_model.hpp"
#include "test_folder.hpp"

namespace meshparticles::testing {
namespace {

class CorrespondenceOutputs : public ::testing::Test {
 protected:
  // Three shapes of four particles each, particle i in the triangle of corners i, i + 1, i + 2
  // (its heaviest, i + 1).
  PopulationCorrespondence population() const {
    PopulationCorrespondence result;
    for (std::size_t s = 0; s < 3; ++s) {
      ShapeCorrespondence shape;
      shape.mesh = shapes_[s];
      shape.particles.resize(4, 3);
      shape.particles << 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1 + 0.1 * double(s);
      shape.particles *= (1.0 + 0.5 * double(s)) / 3.0;  // nine digits to write
      for (std::uint32_t i = 0; i < 4; ++i) shape.locations.push_back({{i, i + 1, i + 2}, {0.25, 0.5, 0.25}});
      result.shapes.push_back(shape);
    }
    return result;
  }

  static std::vector<std::string> lines_of(const std::filesystem::path& file) {
    std::ifstream in(file);
    std::vector<std::string> lines;
    for (std::string line; std::getline(in, line);) lines.push_back(line);
    return lines;
  }

  const TestFolder folder_{"mp_correspondence_outputs"};
  const std::filesystem::path directory_ = folder_ / "out";
  const std::vector<std::string> shapes_{"/data/a.off", "/data/b.ply", "/data/a.stl"};
};

TEST_F(CorrespondenceOutputs, WritesEveryShapesFilesTheModelAndTheSummary) {
  prepare_correspondence_directory(directory_, shapes_);
  const PopulationCorrespondence result = population();
  std::vector<PointSet> sets;
  for (const ShapeCorrespondence& shape : result.shapes) sets.push_back(shape.particles);
  const ShapeModel model = build_shape_model(sets, true, 10, 1, true);
  const ShapeModelOutputs outputs{shapes_, &model, {{"particles", 4}}};
  write_correspondence(directory_, result, outputs, {{"method", "test"}, {"shapes", 3}});

  const std::vector<std::string> stems{"000_a", "001_b", "002_a"};  // unique whatever the names
  for (std::size_t s = 0; s < stems.size(); ++s) {
    const std::vector<std::string> particles = lines_of(directory_ / "shapes" / (stems[s] + ".particles"));
    ASSERT_EQ(particles.size(), 4u) << stems[s];
    for (Eigen::Index i = 0; i < 4; ++i) {
      std::istringstream row(particles[std::size_t(i)]);
      double x, y, z;
      row >> x >> y >> z;
      EXPECT_NEAR(x, result.shapes[s].particles(i, 0), 1e-9) << stems[s] << " row " << i;
      EXPECT_NEAR(y, result.shapes[s].particles(i, 1), 1e-9);
      EXPECT_NEAR(z, result.shapes[s].particles(i, 2), 1e-9);
    }
    const std::vector<std::string> csv = lines_of(directory_ / "shapes" / (stems[s] + ".csv"));
    ASSERT_EQ(csv.size(), 5u) << stems[s];
    EXPECT_EQ(csv[0], "particle,vertex,x,y,z,corner_a,corner_b,corner_c,weight_a,weight_b,weight_c");
    EXPECT_EQ(csv[3].substr(0, 4), "2,3,") << "particle 2, its heaviest corner";
    EXPECT_NE(csv[3].find(",2,3,4,0.25,0.5,0.25"), std::string::npos) << csv[3];
  }
  EXPECT_EQ(std::distance(std::filesystem::directory_iterator(directory_ / "shapes"),
                          std::filesystem::directory_iterator()),
            6);
  EXPECT_TRUE(std::filesystem::exists(directory_ / "model" / "model.json"));
  std::ifstream summary(directory_ / "summary.json");
  EXPECT_EQ(nlohmann::json::parse(summary), (nlohmann::json{{"method", "test"}, {"shapes", 3}}));

  // The same outputs again replace them: the folder is correspond's own.
  EXPECT_NO_THROW(prepare_correspondence_directory(directory_, shapes_));
}

TEST_F(CorrespondenceOutputs, AFolderHoldingAnythingElseIsRefusedBeforeTheWork) {
  std::filesystem::create_directories(directory_);
  std::ofstream(directory_ / "notes.txt") << "mine\n";
  try {
    prepare_correspondence_directory(directory_, shapes_);
    FAIL() << "a folder of the user's own was taken";
  } catch (const UserError& error) {
    EXPECT_NE(std::string(error.what()).find("holds notes.txt, which is not an output of correspond"),
              std::string::npos)
        << error.what();
  }
  EXPECT_TRUE(std::filesystem::exists(directory_ / "notes.txt"));
  // A shapes/ folder with a file no shape of these inputs writes: refused too, nothing removed.
  std::filesystem::remove(directory_ / "notes.txt");
  std::filesystem::create_directories(directory_ / "shapes");
  std::ofstream(directory_ / "shapes" / "000_other.particles") << "0 0 0\n";
  EXPECT_THROW(prepare_correspondence_directory(directory_, shapes_), UserError);
  EXPECT_TRUE(std::filesystem::exists(directory_ / "shapes" / "000_other.particles"));
}

}  // namespace
}  // namespace meshparticles::testing
