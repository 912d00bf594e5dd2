#pragma once
// The options of a run, declared once, a row each: `run` and `batch`
// register each row as --NAME (cli/run_options.cpp) and the Python module
// takes each as a keyword (python/run_settings.cpp). Both check a value as
// its row says (whole numbers within the row's range, words among the row's
// words on the command line), store it in the row's field of
// RunOptionValues, and turn those into a RunRequest by run_request
// (options/run_option_values.hpp): a new option is a row, a field and the line
// of run_request that reads it. run()'s signature in
// python/meshparticles/__init__.py must list exactly the rows' keywords
// (tests/run_option_table_test.cpp holds it to the table).
#include <filesystem>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "options/number_options.hpp"
#include "options/run_option_values.hpp"

namespace meshparticles {

// Where a row's value goes; its type is the row's kind: a whole number, a
// positive number, a word, a path or a flag.
using WholeField = std::optional<std::uint64_t> RunOptionValues::*;
using PositiveField = std::optional<double> RunOptionValues::*;
using WordField = std::optional<std::string> RunOptionValues::*;
using PathField = std::optional<std::filesystem::path> RunOptionValues::*;
using FlagField = bool RunOptionValues::*;
using RunOptionField = std::variant<WholeField, PositiveField, WordField, PathField, FlagField>;

struct RunOptionSpec {
  std::string name;     // the command line's long name, without "--"
  std::string keyword;  // the Python keyword of run() and batch(); empty: none (strict: read_mesh takes it)
  RunOptionField field;
  std::string help;                  // --help's text, and the one run()'s docstring points to
  WholeRange range{};                // a whole number's
  std::vector<std::string> words{};  // the words a word option takes; empty: any (a device's name)
  std::string short_name{};          // "n" for -n; empty: none
  std::string shown_default{};       // what --help shows as the default ("=500"); empty: none shown

  // "-n,--particles": the names CLI11 registers, and (as "-n/--particles") the refusals say.
  std::string command_line_names() const;
};

// Every option of `run` but the mesh and --out, in the order --help lists them.
const std::vector<RunOptionSpec>& run_option_table();

// The row of the option named `name` (the command line's); std::logic_error
// for a name not in the table.
const RunOptionSpec& run_option(const std::string& name);

// --geodesic's help where a command has no default rule of its own to add:
// the solvers.
std::string geodesic_solver_help();

}  // namespace meshparticles
