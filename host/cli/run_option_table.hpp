#pragma once
// The options of a run, declared once: `run` and `batch` register each as
// --NAME (cli/run_options.cpp) and the Python module takes each as a keyword
// (python/run_settings.cpp), both checking it as its row says: whole
// numbers within the row's range, words among the row's words. run()'s
// signature in python/meshparticles/__init__.py must list exactly these
// keywords (tests/run_option_table_test.cpp holds it to the table).
#include <string>
#include <vector>

#include "cli/number_options.hpp"

namespace meshparticles {

enum class RunOptionKind { whole, positive, word, path, flag };

struct RunOptionSpec {
  std::string name;     // the command line's long name, without "--"
  std::string keyword;  // the Python keyword
  RunOptionKind kind;
  WholeRange range{};               // a whole number's
  std::vector<std::string> words{};  // the words a word option takes; empty: any (a device's name)
};

// Every option of `run` but the mesh, --out and --strict (a mesh-reading
// option: read_mesh takes strict=), in the order --help lists them.
const std::vector<RunOptionSpec>& run_option_table();

// The row of the option named `name` (the command line's); std::logic_error
// for a name not in the table.
const RunOptionSpec& run_option(const std::string& name);

}  // namespace meshparticles
