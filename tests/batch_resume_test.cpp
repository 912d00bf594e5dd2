// A resumed batch keeps a mesh's output only when every byte of its six
// files is as the run wrote it (batch/reusable_output.hpp): one byte edited
// anywhere, report.json included, and that mesh alone is computed again.
// The runs are spread's on two small meshes, on the host.
#include <gtest/gtest.h>

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

#include "batch/batch_plan.hpp"
#include "batch/mesh_job.hpp"
#include "reports/file_digest.hpp"
#include "reports/output_digests.hpp"
#include "reports/run_outputs.hpp"
#include "test_files.hpp"

namespace meshparticles::testing {
namespace {


// In place, as an editor saving the file would leave it to a later resume.
void overwrite(const std::filesystem::path& file, const std::string& bytes) {
  std::ofstream(file, std::ios::binary | std::ios::trunc) << bytes;
}

// Another byte of the same kind, so that most edits of report.json still
// parse: the next digit or letter, a space for a newline, a tab for a space.
char edited(char byte) {
  if (byte >= '0' && byte <= '9') return byte == '9' ? '0' : char(byte + 1);
  if ((byte >= 'a' && byte < 'z') || (byte >= 'A' && byte < 'Z')) return char(byte + 1);
  if (byte == '\n') return ' ';
  if (byte == ' ') return '\t';
  return char(byte ^ 1);
}

class BatchResume : public ::testing::Test {
 protected:
  void SetUp() override {
    root_ = std::filesystem::temp_directory_path() / ("mp_resume_" + std::to_string(::getpid()));
    std::filesystem::remove_all(root_);
    std::filesystem::create_directories(root_ / "meshes");
    std::filesystem::copy_file(std::string(MESHES_DIR) + "/high_valence.off", root_ / "meshes" / "edited.off");
    std::filesystem::copy_file(std::string(MESHES_DIR) + "/tetrahedron.off", root_ / "meshes" / "untouched.off");
    BatchRequest request;
    request.inputs = {(root_ / "meshes").string()};
    request.out = root_ / "out";
    request.count = {ParticleCount::Rule::fixed, 4};
    request.run.quiet = true;
    request.quiet = true;
    plan_ = plan_batch(request, false);
    ASSERT_EQ(kept_by_a_pass(), (std::map<std::string, bool>{{"edited", false}, {"untouched", false}}));
  }
  void TearDown() override { std::filesystem::remove_all(root_); }

  // One pass of the batch over every mesh: each output folder's name, and
  // whether its earlier output was kept.
  std::map<std::string, bool> kept_by_a_pass() {
    std::map<std::string, bool> kept;
    for (std::size_t i = 0; i < plan_.items.size(); ++i) {
      const MeshOutcome outcome = run_batch_mesh(plan_, i);
      EXPECT_EQ(outcome.row["status"], "ok") << outcome.row.dump();
      kept[plan_.items[i].output_name] = outcome.reused;
    }
    return kept;
  }

  std::filesystem::path edited_file(const std::string& name) const { return root_ / "out" / "edited" / name; }

  const std::map<std::string, bool> only_edited_redone_{{"edited", false}, {"untouched", true}};
  const std::map<std::string, bool> both_kept_{{"edited", true}, {"untouched", true}};
  std::filesystem::path root_;
  BatchPlan plan_;
};

TEST_F(BatchResume, ReportRecordsTheSizeAndDigestOfEveryOtherFile) {
  const auto report = nlohmann::json::parse(slurp(edited_file("report.json")));
  ASSERT_TRUE(report.contains("outputs"));
  EXPECT_EQ(report["outputs"].size(), kRunOutputFiles.size() - 1);
  for (const std::string& name : kRunOutputFiles) {
    if (name == "report.json") continue;
    SCOPED_TRACE(name);
    EXPECT_EQ(report["outputs"][name]["bytes"], std::filesystem::file_size(edited_file(name)));
    EXPECT_EQ(report["outputs"][name]["sha256"], file_sha256(edited_file(name)));
  }
  nlohmann::json rest = report;
  rest.erase("report_sha256");
  EXPECT_EQ(report["report_sha256"], text_sha256(rest.dump(2) + "\n"));
  EXPECT_EQ(kept_by_a_pass(), both_kept_);
}

// The first, middle and last byte of each file, each edited alone (same
// size): the edited mesh is computed again, the other kept; the new output
// is then kept in turn.
TEST_F(BatchResume, OneEditedByteInAnyFileRedoesThatMeshAlone) {
  for (const std::string& name : kRunOutputFiles) {
    const std::string pristine = slurp(edited_file(name));
    for (const std::string where : {"first", "middle", "last"}) {
      // Read again each time: a recomputed report.json has other timings, and another length.
      std::string bytes = slurp(edited_file(name));
      ASSERT_GE(bytes.size(), 3u) << name;
      const std::size_t at = where == "first" ? 0 : where == "middle" ? bytes.size() / 2 : bytes.size() - 1;
      SCOPED_TRACE(name + ", " + where + " byte (" + std::to_string(at) + " of " + std::to_string(bytes.size()) +
                   "): " + std::to_string(int(bytes[at])) + " -> " + std::to_string(int(edited(bytes[at]))));
      bytes[at] = edited(bytes[at]);
      overwrite(edited_file(name), bytes);
      EXPECT_EQ(kept_by_a_pass(), only_edited_redone_);
      // The run is deterministic: its particle and mesh files come back byte
      // for byte (report.json's timings differ).
      if (name != "report.json") {
        EXPECT_TRUE(slurp(edited_file(name)) == pristine) << "the edit is still there";
      }
      EXPECT_EQ(kept_by_a_pass(), both_kept_);
    }
  }
}

// Edits of report.json that still parse: a figure of the summary changed
// (nothing but report.json's own digest can tell), and white space changed
// (the same content, but not the text a run writes).
TEST_F(BatchResume, ReportEditsThatStillParseRedoTheMesh) {
  const auto expect_redone_after = [&](const std::string& what, bool same_content, const auto& edit) {
    SCOPED_TRACE(what);
    const std::string before = slurp(edited_file("report.json"));
    std::string after = before;
    edit(after);
    ASSERT_NE(after, before);
    const auto parsed = nlohmann::json::parse(after, nullptr, /*allow_exceptions=*/false);
    ASSERT_TRUE(parsed.is_object()) << "the edit should leave JSON";
    EXPECT_EQ(parsed == nlohmann::json::parse(before), same_content);
    overwrite(edited_file("report.json"), after);
    EXPECT_EQ(kept_by_a_pass(), only_edited_redone_);
  };
  expect_redone_after("a digit of the energy", false, [](std::string& text) {
    const std::size_t digit = text.find_first_of("123456789", text.find("\"energy\": ", text.find("\"quality\"")));
    text[digit] = text[digit] == '7' ? '8' : '7';
  });
  expect_redone_after("an indenting space as a tab", true, [](std::string& text) { text[text.find("\n ") + 1] = '\t'; });
  expect_redone_after("a blank line at the end", true, [](std::string& text) { text += "\n"; });
}

// An output written before report.json recorded the digests is computed
// again: nothing else proves its files.
TEST_F(BatchResume, ReportWithoutDigestsRedoesTheMesh) {
  auto report = nlohmann::json::parse(slurp(edited_file("report.json")));
  report.erase("outputs");
  report.erase("report_sha256");
  overwrite(edited_file("report.json"), report.dump(2) + "\n");
  EXPECT_EQ(kept_by_a_pass(), only_edited_redone_);
}

// An output another version wrote, intact and signed, is computed again:
// the same inputs may give other particles there.
TEST_F(BatchResume, AnotherVersionsOutputRedoesTheMesh) {
  auto report = nlohmann::json::parse(slurp(edited_file("report.json")));
  report.erase("outputs");
  report.erase("report_sha256");
  report["version"] = "0.0.1";
  overwrite(edited_file("report.json"), digested_report_text(report, root_ / "out" / "edited"));
  EXPECT_EQ(kept_by_a_pass(), only_edited_redone_);
}

}  // namespace
}  // namespace meshparticles::testing
