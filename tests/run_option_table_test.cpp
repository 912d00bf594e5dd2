// The run options' table, whole and against the Python module's wrappers:
// every row has its help and a field of its own that run_request reads;
// run()'s signature lists exactly the table's keywords, in its order, and
// hands each on to the core; quality() and compare() take only keywords of
// the table (besides their own). A row half added, or a keyword added on one
// side only, fails here.
#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "common/overloaded.hpp"
#include "options/run_option_table.hpp"

namespace meshparticles::testing {
namespace {

std::string python_wrappers() {
  std::ifstream file(std::string(PYTHON_PACKAGE_DIR) + "/__init__.py");
  std::stringstream text;
  text << file.rdbuf();
  return text.str();
}

// The text of `def NAME(` up to the end of its body (the next top-level line).
std::string function_text(const std::string& source, const std::string& name) {
  const auto start = source.find("\ndef " + name + "(");
  if (start == std::string::npos) return {};
  const auto end = source.find("\n\n\ndef ", start + 1);
  return source.substr(start, end == std::string::npos ? std::string::npos : end - start);
}

// The parameter names of a def: "    name: type" lines up to the closing ")".
std::vector<std::string> parameters(const std::string& function) {
  const std::string signature = function.substr(0, function.find("\n) ->"));
  std::vector<std::string> names;
  const std::regex parameter(R"(\n    (\w+):)");
  for (auto it = std::sregex_iterator(signature.begin(), signature.end(), parameter); it != std::sregex_iterator();
       ++it) {
    names.push_back((*it)[1]);
  }
  return names;
}

std::vector<std::string> table_keywords() {
  std::vector<std::string> keywords;
  for (const RunOptionSpec& option : run_option_table()) {
    if (!option.keyword.empty()) keywords.push_back(option.keyword);
  }
  return keywords;
}

bool in_table(const std::string& keyword) {
  for (const RunOptionSpec& option : run_option_table()) {
    if (option.keyword == keyword) return true;
  }
  return false;
}

TEST(RunOptionTable, PythonRunTakesExactlyTheTablesKeywordsInItsOrder) {
  const std::string run = function_text(python_wrappers(), "run");
  ASSERT_FALSE(run.empty());
  std::vector<std::string> keywords = parameters(run);
  // mesh is the positional input, cancel the Python-only stop.
  ASSERT_GE(keywords.size(), 2u);
  EXPECT_EQ(keywords.front(), "mesh");
  EXPECT_EQ(keywords.back(), "cancel");
  keywords = std::vector<std::string>(keywords.begin() + 1, keywords.end() - 1);
  EXPECT_EQ(keywords, table_keywords());
  for (const std::string& keyword : table_keywords()) {
    EXPECT_NE(run.find("        " + keyword + "=" + keyword + ",\n"), std::string::npos)
        << keyword << " is not handed on to _core.run";
  }
}

TEST(RunOptionTable, PythonQualityAndCompareTakeOnlyTableKeywords) {
  const std::string wrappers = python_wrappers();
  for (const char* function : {"quality", "compare"}) {
    const std::vector<std::string> names = parameters(function_text(wrappers, function));
    ASSERT_FALSE(names.empty()) << function;
    for (const std::string& name : names) {
      if (name == "mesh" || name == "points" || name == "a" || name == "b" || name == "refine" || name == "cancel") {
        continue;  // their own
      }
      EXPECT_TRUE(in_table(name)) << function << "() takes " << name << ", which the table lacks";
    }
  }
}

TEST(RunOptionTable, NamesAreUniqueAndKeywordsFollowThem) {
  const auto& table = run_option_table();
  for (std::size_t i = 0; i < table.size(); ++i) {
    for (std::size_t j = i + 1; j < table.size(); ++j) EXPECT_NE(table[i].name, table[j].name);
    if (table[i].name != "particles" && table[i].name != "strict") {
      std::string keyword = table[i].name;
      for (char& c : keyword) c = c == '-' ? '_' : c;
      EXPECT_EQ(table[i].keyword, keyword);
    }
  }
  EXPECT_EQ(run_option("particles").keyword, "n");
  EXPECT_EQ(run_option("strict").keyword, "");  // read_mesh(strict=): the mesh is read before run()
  EXPECT_THROW(run_option("no-such-option"), std::logic_error);
}

TEST(RunOptionTable, EveryRowHasItsHelpAndShowsAValidDefault) {
  for (const RunOptionSpec& option : run_option_table()) {
    EXPECT_FALSE(option.help.empty()) << "--" << option.name << " has no help";
    if (option.shown_default.empty() || option.name == "backend") continue;  // backend's is a rule, in words
    if (const auto* field = std::get_if<WordField>(&option.field); field && !option.words.empty()) {
      EXPECT_NE(std::find(option.words.begin(), option.words.end(), option.shown_default), option.words.end())
          << "--" << option.name << "'s default " << option.shown_default << " is not one of its words";
    }
    if (std::holds_alternative<WholeField>(option.field)) {
      const std::uint64_t shown = std::stoull(option.shown_default);
      EXPECT_TRUE(shown >= option.range.min && shown <= option.range.max) << "--" << option.name;
    }
  }
}

// Everything a request holds, as text: two requests that print alike are alike.
std::string described(const RunRequest& request) {
  std::ostringstream text;
  const auto optional = [](const auto& value) {
    std::ostringstream out;
    if (value) out << *value; else out << "-";
    return out.str();
  };
  const BackendRequest& backend = request.backend;
  const GeodesicsRequest& geodesics = request.distances.geodesics;
  text << request.particles << " " << (request.method ? method_option_name(*request.method) : "-") << " "
       << optional(request.vertices_per_particle) << " " << optional(request.relax_rounds) << " "
       << request.max_iterations << " " << backend.name << " " << backend.device << " "
       << optional(backend.work_group_size) << " " << optional(backend.tile_size) << " "
       << (backend.weights ? weight_format_name(*backend.weights) : "-") << " " << optional(backend.rebuild_every)
       << " " << optional(backend.tuning_file) << " " << (request.scheme ? scheme_name(*request.scheme) : "-") << " "
       << optional(request.colors) << " " << init_name(request.init) << " " << optional(request.start_vertex) << " "
       << request.seed << " " << potential_name(request.potential) << " " << optional(request.sigma) << " "
       << store_kind_name(request.distances.kind) << " " << optional(request.distances.cutoff) << " "
       << method_name(geodesics.method) << " " << optional(geodesics.cache_directory) << " " << geodesics.threads
       << " " << geodesics.quiet << " " << geodesics.device << " " << request.geodesic_given << " " << request.quiet;
  return text.str();
}

// A value of the row's kind other than its default: the largest whole
// number, a word other than the one shown as the default, ...
void give_other_value(const RunOptionSpec& option, RunOptionValues& values) {
  std::visit(Overloaded{
                 [&](WholeField field) { values.*field = option.range.max; },
                 [&](PositiveField field) { values.*field = 2.5; },
                 [&](WordField field) {
                   const auto other = std::find_if(option.words.begin(), option.words.end(),
                                                   [&](const std::string& w) { return w != option.shown_default; });
                   values.*field = other == option.words.end() ? std::string("some device") : *other;
                 },
                 [&](PathField field) { values.*field = std::filesystem::path("/no/such/option/path"); },
                 [&](FlagField field) { values.*field = true; },
             },
             option.field);
}

TEST(RunOptionTable, EveryRowReachesTheRequestByItsOwnField) {
  const RunOptionValues none;
  const std::string defaults = described(run_request(none));
  // Not given, each option is RunRequest's own default.
  const RunRequest request;
  EXPECT_EQ(run_request(none).particles, request.particles);
  EXPECT_EQ(run_request(none).max_iterations, request.max_iterations);
  EXPECT_EQ(run_request(none).backend.name, request.backend.name);
  EXPECT_FALSE(run_request(none).geodesic_given);
  std::vector<std::string> seen;
  for (const RunOptionSpec& option : run_option_table()) {
    RunOptionValues given;
    give_other_value(option, given);
    if (option.name == "strict") {
      EXPECT_TRUE(mesh_read_options(given).strict);
      continue;
    }
    const std::string changed = described(run_request(given));
    EXPECT_NE(changed, defaults) << "--" << option.name << " given changes nothing in the request";
    EXPECT_EQ(std::find(seen.begin(), seen.end(), changed), seen.end())
        << "--" << option.name << " changes the request as an earlier row does: two rows, one field?";
    seen.push_back(changed);
  }
}

}  // namespace
}  // namespace meshparticles::testing
