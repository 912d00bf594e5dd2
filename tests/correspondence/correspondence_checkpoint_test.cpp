// correspondence/correspondence_checkpoint: entries read back as written; a
// run of the same request resumes, of another starts anew; an entry edited,
// cut short or moved is refused, the folder removed.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>

#include "common/user_error.hpp"
#include "correspondence/correspondence_checkpoint.hpp"
#include "test_folder.hpp"

namespace meshparticles::testing {
namespace {

class CheckpointTest : public ::testing::Test {
 protected:
  CorrespondCheckpoint open(const nlohmann::json& fingerprint) const {
    return CorrespondCheckpoint(directory_.path(), fingerprint, true, true);
  }
  static nlohmann::json identity(const nlohmann::json& values) { return values; }
  std::filesystem::path folder() const { return directory_ / CorrespondCheckpoint::kFolder; }
  std::filesystem::path entry(const std::string& name) const { return folder() / (name + ".json"); }

  const TestFolder directory_{"mp_checkpoint"};
  const nlohmann::json fingerprint_ = {{"particles", 8}, {"inputs", {"a.off", "b.off"}}};
  const nlohmann::json values_ = {{"rows", {0.1, 1.0 / 3.0, -2.5e-300}}, {"name", "t"}};
};

TEST_F(CheckpointTest, EntriesReadBackAsWrittenAndAResumeFindsThem) {
  {
    const CorrespondCheckpoint checkpoint = open(fingerprint_);
    EXPECT_FALSE(checkpoint.read("template", identity));
    checkpoint.write("template", values_);
    checkpoint.write(shape_entry("transfer", 7), values_);
    EXPECT_EQ(checkpoint.read("template", identity).value_or(nullptr), values_);
  }
  EXPECT_TRUE(std::filesystem::exists(entry("transfer/007")));
  const CorrespondCheckpoint resumed = open(fingerprint_);
  EXPECT_EQ(resumed.read("template", identity).value_or(nullptr), values_);
  EXPECT_EQ(resumed.read("transfer/007", identity).value_or(nullptr), values_);
}

TEST_F(CheckpointTest, ARunOfAnotherRequestStartsAnew) {
  open(fingerprint_).write("template", values_);
  nlohmann::json other = fingerprint_;
  other["particles"] = 9;
  const CorrespondCheckpoint anew = open(other);
  EXPECT_FALSE(anew.read("template", identity));
  EXPECT_FALSE(std::filesystem::exists(entry("template")));
}

// Each way an entry can be damaged: the leader finds it before the run
// takes any, and the whole checkpoint goes.
TEST_F(CheckpointTest, ADamagedEntryClearsTheCheckpoint) {
  const auto damage = [&](const std::string& how) {
    open(fingerprint_).write("template", values_);
    open(fingerprint_).write("pack/001", values_);
    std::string text = text_of(entry("template"));
    if (how == "edited") {  // still JSON, the same size: only the SHA-256 tells
      const std::size_t digit = text.find("0.1", text.find('\n'));
      ASSERT_NE(digit, std::string::npos);
      text[digit + 2] = '2';
    } else if (how == "cut short") {
      text.resize(text.size() - 5);
    } else if (how == "moved") {
      std::filesystem::rename(entry("pack/001"), entry("pack/002"));
    } else if (how == "stray file") {
      std::ofstream(folder() / "notes.txt") << "mine\n";
    }
    if (how == "edited" || how == "cut short") std::ofstream(entry("template"), std::ios::binary) << text;
    const CorrespondCheckpoint checked = open(fingerprint_);
    EXPECT_FALSE(checked.read("template", identity)) << how;
    EXPECT_FALSE(checked.read("pack/001", identity)) << how;
    EXPECT_FALSE(std::filesystem::exists(folder() / "pack")) << how;
  };
  for (const char* how : {"edited", "cut short", "moved", "stray file"}) damage(how);
}

// An entry damaged after the leader's check, or values no run could have
// written: the read refuses the run in one line, after removing the folder.
TEST_F(CheckpointTest, AReadOfADamagedEntryRefusesAndRemovesTheFolder) {
  const CorrespondCheckpoint checkpoint = open(fingerprint_);
  checkpoint.write("template", values_);
  std::string text = text_of(entry("template"));
  text.back() = ' ';
  std::ofstream(entry("template"), std::ios::binary) << text;
  try {
    checkpoint.read("template", identity);
    FAIL() << "a damaged entry was taken";
  } catch (const UserError& error) {
    const std::string message = error.what();
    EXPECT_NE(message.find("template.json is damaged"), std::string::npos) << message;
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
  }
  EXPECT_FALSE(std::filesystem::exists(folder()));
  checkpoint.write("transfer/000", values_);  // refused runs write nothing more
  EXPECT_FALSE(std::filesystem::exists(folder()));

  const CorrespondCheckpoint again = open(fingerprint_);
  again.write("template", values_);
  EXPECT_THROW(again.read("template", [](const nlohmann::json&) -> int { throw std::invalid_argument("row short"); }),
               UserError);
  EXPECT_FALSE(std::filesystem::exists(folder()));
}

TEST(CheckpointEntries, ShapeEntriesNameTheStageAndTheShape) {
  EXPECT_EQ(shape_entry("transfer", 7), "transfer/007");
  EXPECT_EQ(shape_entry("pack", 1234), "pack/1234");
}

}  // namespace
}  // namespace meshparticles::testing
