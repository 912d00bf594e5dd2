// The run options' table against the Python module's wrappers: run()'s
// signature lists exactly the table's keywords, in its order, and hands each
// on to the core; quality() and compare() take only keywords of the table
// (besides their own). A keyword added on one side only fails here.
#include <gtest/gtest.h>

#include <fstream>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "cli/run_option_table.hpp"

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
  for (const RunOptionSpec& option : run_option_table()) keywords.push_back(option.keyword);
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
    if (table[i].name != "particles") {
      std::string keyword = table[i].name;
      for (char& c : keyword) c = c == '-' ? '_' : c;
      EXPECT_EQ(table[i].keyword, keyword);
    }
  }
  EXPECT_EQ(run_option("particles").keyword, "n");
  EXPECT_THROW(run_option("no-such-option"), std::logic_error);
}

}  // namespace
}  // namespace meshparticles::testing
